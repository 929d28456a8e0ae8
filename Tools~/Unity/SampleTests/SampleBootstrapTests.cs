using System;
using System.Collections;
using HookeRope.Samples.CollisionBend;
using HookeRope.Samples.FallArrest;
using HookeRope.Samples.NeckingAndFracture;
using HookeRope.Samples.PoissonSweep;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.StandIn.SampleChecks
{
    /// <summary>
    /// Play Mode through the stand-in's player loop: each sample's bootstrap builds its scene in Start and runs for
    /// 2 s of simulated time (Unity's default 0.02 s fixed step, 90 Hz frames); then the sample's own physics is
    /// checked against numbers. Samples~ is not compiled by Unity until a user imports a sample, so these checks
    /// live with the stand-in rather than in the package's Tests/.
    /// </summary>
    public sealed class SampleBootstrapTests
    {
        const float G = 9.81f;

        [TearDown]
        public void TearDown()
        {
            var objects = World.Objects;
            for (int i = objects.Count - 1; i >= 0; i--)
                if (i < objects.Count && objects[i].transform.parent == null) UnityEngine.Object.DestroyImmediate(objects[i]);
        }

        static IEnumerator RunSeconds(float seconds)
        {
            float end = Time.time + seconds;
            while (Time.time < end) yield return null;
        }

        static T Find<T>(string name) where T : Component
        {
            var go = GameObject.Find(name);
            Assert.That(go, Is.Not.Null, "the sample builds '" + name + "'");
            return go.GetComponent<T>();
        }

        [UnityTest]
        public IEnumerator FallArrestSampleArrestsTheWorker()
        {
            float start = Time.time;
            new GameObject("Fall Arrest", typeof(FallArrestBootstrap));
            yield return null;
            var lanyard = Find<ElasticRope>("Lanyard");
            var worker = Find<Rigidbody>("Worker");
            float lowestDRing = float.PositiveInfinity;
            while (Time.time < start + 2f)
            {
                lowestDRing = Math.Min(lowestDRing, worker.position.y + 0.7f);   // the D-ring sits 0.7 m above the centre
                yield return null;
            }

            // the sample's defaults: 100 kg, 2 m lanyard of E·A 30 kN, 4 m free fall, anchor at 9 m
            float weight = 100f * G, k = 30000f / 2f;
            float expected = weight + (float)Math.Sqrt(weight * weight + 2f * weight * k * 4f);
            // at Unity's default 50 Hz fixed step the backward-Euler chain solve and the 2 ms damping lower the
            // arrest peak by 4.8 %; never above the undamped energy balance
            Assert.That(lanyard.PeakArrestForce, Is.EqualTo(expected).Within(6).Percent);
            Assert.That(lanyard.PeakArrestForce, Is.LessThan(expected));
            Assert.That(lanyard.MeetsEn355, Is.False, "a 30 kN lanyard without an absorber exceeds EN 355");
            Assert.That(lanyard.IsBroken, Is.False);
            // the lowest point: the taut length plus the stretch at the peak force, F/k
            Assert.That(lowestDRing, Is.EqualTo(9f - 2f - lanyard.PeakArrestForce / k).Within(0.03f));
        }

        [UnityTest]
        public IEnumerator FallArrestSampleArrestsTheCharacterControllerWorkerAsTheRigidbodyWorker()
        {
            float start = Time.time;
            new GameObject("Fall Arrest", typeof(FallArrestBootstrap));
            yield return null;
            var lanyard = Find<ElasticRope>("Lanyard");
            var characterLanyard = Find<ElasticRope>("Lanyard (CharacterController)");
            var rig = Find<CharacterController>("Worker (CharacterController)");
            Assert.That(rig.GetComponent<Rigidbody>(), Is.Null, "the rig has no Rigidbody");
            Assert.That(characterLanyard.EndAttachment.Kind, Is.EqualTo(RopeEndKind.KinematicRig));
            float lowestDRing = float.PositiveInfinity;
            while (Time.time < start + 2f)
            {
                lowestDRing = Math.Min(lowestDRing, rig.transform.position.y + 0.7f);
                yield return null;
            }

            float weight = 100f * G, k = 30000f / 2f;
            float expected = weight + (float)Math.Sqrt(weight * weight + 2f * weight * k * 4f);
            TestContext.WriteLine("peak arrest force: Rigidbody worker " + lanyard.PeakArrestForce + " N, CharacterController worker " +
                                  characterLanyard.PeakArrestForce + " N, energy balance " + expected + " N");
            Assert.That(characterLanyard.PeakArrestForce, Is.EqualTo(lanyard.PeakArrestForce).Within(2).Percent);
            Assert.That(characterLanyard.PeakArrestForce, Is.EqualTo(expected).Within(6).Percent);
            Assert.That(characterLanyard.PeakArrestForce, Is.LessThan(expected));
            Assert.That(lowestDRing, Is.EqualTo(9f - 2f - characterLanyard.PeakArrestForce / k).Within(0.03f));
            // the controller moved itself: its velocity is its last Move over the fixed step
            Assert.That(rig.velocity.y, Is.EqualTo(characterLanyard.EndRigDisplacement.y / Time.fixedDeltaTime).Within(1e-3f));
        }

        [UnityTest]
        public IEnumerator CollisionBendSampleDrapesBothRopes()
        {
            new GameObject("Collision Bend", typeof(CollisionBendBootstrap));
            yield return RunSeconds(2f);

            // grips lowered from 2 m towards 0.3 m over 3 s (one step of 0.02 s per FixedUpdate, the first at t = 0):
            // about 0.86 m after 2 s, below the shapes' tops at 1.25 m
            float grip = 2f - 1.7f * Math.Min(1f, (Time.fixedTime + Time.fixedDeltaTime) / 3f);
            foreach (var name in new[] { "Rope over cylinder", "Rope over box" })
            {
                var rope = Find<ElasticRope>(name);
                var middle = rope.GetParticlePosition(rope.ParticleCount / 2);
                Assert.That(middle.y, Is.GreaterThan(1.25f).And.LessThan(1.25f + 4f * rope.Radius), name + " rests on its shape");
                Assert.That(rope.GetParticlePosition(0).y, Is.EqualTo(grip).Within(1e-4f), name + " follows its grip");
            }
            // the cylinder primitive carries a CapsuleCollider (radius 0.25 m after scaling): no particle inside it
            var over = Find<ElasticRope>("Rope over cylinder");
            for (int i = 0; i < over.ParticleCount; i++)
            {
                var p = over.GetParticlePosition(i);
                float distance = (float)Math.Sqrt(p.x * p.x + (p.y - 1f) * (p.y - 1f));
                if (Math.Abs(p.z) < 0.35f) Assert.That(distance, Is.GreaterThan(0.25f + over.GetParticleRadius(i) - 0.005f), "particle " + i);
            }
        }

        [UnityTest]
        public IEnumerator NeckingAndFractureSampleThinsUniformlyBeforeTheNeck()
        {
            new GameObject("Necking And Fracture", typeof(NeckingAndFractureBootstrap));
            yield return RunSeconds(2f);

            // pulled at 0.12 m/s for 2 s: strain 0.2 on 1.2 m; ν = 0.5 thins to sqrt(1 + 2ν(1/1.2 − 1)) = 0.913 R > r_min
            int[] radial = { 8, 16, 32 };
            int previousVertices = 0;
            for (int i = 0; i < 3; i++)
            {
                string fraction = new[] { "0.8", "0.75", "0.7" }[i];
                var rope = Find<ElasticRope>("Rope r_min=" + fraction + "R");
                float strain = rope.Elongation / rope.RestLength;
                Assert.That(strain, Is.EqualTo(0.2f).Within(0.01f));
                float expected = rope.Radius * (float)Math.Sqrt(1.0 + 2.0 * 0.5 * (1.0 / (1.0 + strain) - 1.0));
                Assert.That(rope.GetParticleRadius(rope.ParticleCount / 4), Is.EqualTo(expected).Within(0.01f * expected));
                Assert.That(rope.IsBroken, Is.False);
                var mesh = rope.GetComponent<MeshFilter>().sharedMesh;
                Assert.That(mesh, Is.Not.Null, "LateUpdate built the mesh");
                Assert.That(mesh.vertexCount, Is.GreaterThan(previousVertices), radial[i] + " radial segments give more vertices");
                previousVertices = mesh.vertexCount;
            }
        }

        [UnityTest]
        public IEnumerator PoissonSweepSampleFollowsThePoissonRadius()
        {
            new GameObject("Poisson Sweep", typeof(PoissonSweepBootstrap));
            yield return RunSeconds(2f);

            // strain(t) = 0.25 (1 − cos(2π t / 6 s)): 0.375 at 2 s; r/R = sqrt(1 + 2ν(1/(1+ε) − 1))
            foreach (float nu in new[] { 0f, 0.3f, 0.5f, -0.8f })
            {
                var rope = Find<ElasticRope>("Rope ν=" + nu);
                float strain = rope.Elongation / rope.RestLength;
                Assert.That(strain, Is.EqualTo(0.375f).Within(0.02f), "ν " + nu);
                float expected = rope.Radius * (float)Math.Sqrt(1.0 + 2.0 * nu * (1.0 / (1.0 + strain) - 1.0));
                Assert.That(rope.GetParticleRadius(rope.ParticleCount / 2), Is.EqualTo(expected).Within(0.015f * rope.Radius), "ν " + nu);
            }
        }
    }
}
