using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): a 100 kg Rigidbody falls 4 m on a 2 m lanyard. The peak arrest force read-out must
    /// match the energy balance of a light linear lanyard, F = M·g + sqrt((M·g)² + 2·M·g·k·h) with k = E·A/L, and
    /// the EN 355 / ANSI Z359.13 verdicts must follow from it.
    /// </summary>
    [TestFixture]
    public sealed class FallArrestReadoutTests
    {
        const float G = 9.81f, Mass = 100f, Length = 2f, FreeFall = 4f;
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        [TestCase(30000f, false, false)]
        [TestCase(5000f, true, true)]
        public void PeakArrestForceMatchesEnergyBalance(float axialStiffness, bool meetsEn355, bool meetsAnsi)
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 20f, 0f));
            var body = _scene.Body("Worker", new Vector3(0.01f, 20f + FreeFall - Length, 0f), Mass);
            var rope = _scene.Rope("Lanyard", anchor.position);
            rope.RestLength = Length;
            rope.AxialStiffness = axialStiffness;
            rope.SegmentCount = 16;
            rope.Substeps = 8;
            rope.Fracture = false;
            rope.StartAttachment.Point = anchor;
            rope.EndAttachment.Body = body;
            rope.Rebuild();

            UnityRopeScene.Run(rope, 600, 0.005f);

            float weight = Mass * G, k = axialStiffness / Length;
            float expected = weight + Mathf_Sqrt(weight * weight + 2f * weight * k * FreeFall);
            Assert.That(rope.PeakArrestForce, Is.EqualTo(expected).Within(0.08f * expected));
            Assert.That(rope.MeetsEn355, Is.EqualTo(meetsEn355));
            Assert.That(rope.MeetsAnsiZ359_13, Is.EqualTo(meetsAnsi));
        }

        static float Mathf_Sqrt(float x) => (float)System.Math.Sqrt(x);
    }
}
