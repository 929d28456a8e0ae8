using System;
using System.Collections.Generic;
using System.Reflection;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// The exact chain solve's <see cref="VectorPath"/> kernels (issue 18: Assemble and the particle pass on
    /// Vector&lt;double&gt; lanes) give the bits of the scalar rows: each scene is stepped once with the vector paths off
    /// and once on, and every particle's position (previous position, sub-float remainder, displacement and its remainder)
    /// and double velocity must match bit for bit after every host step. The scenes cover both integrators, tension-only
    /// ropes with slack segments, bilateral rods that push, contacts with friction, plasticity, a broken segment, 1 and 2
    /// segments and segment counts that are not a multiple of the lanes (the scalar tail).
    /// </summary>
    public sealed class VectorPathBitIdentityTests
    {
        private const int HostSteps = 60;

        private static readonly FieldInfo ChainField = typeof(Rope).GetField("chain", BindingFlags.NonPublic | BindingFlags.Instance);

        public static IEnumerable<string> Scenes => new[]
        {
            "bdf2-swing-61", "be-load-64", "goal-lanyard-64", "slack-tension-only-37", "bilateral-rod-bdf2-24",
            "bilateral-rod-be-19", "sphere-friction-40", "plane-friction-48", "plastic-neck-33", "broken-32", "one-segment",
            "two-segments", "swing-256",
        };

        [TestCaseSource(nameof(Scenes))]
        public void LanesGiveTheScalarBits(string scene)
        {
            bool saved = VectorPath.Enabled;
            try
            {
                VectorPath.Enabled = false;
                List<long[]> scalar = Run(scene);
                VectorPath.Enabled = true;
                List<long[]> lanes = Run(scene);
                for (int step = 0; step < HostSteps; step++)
                    Assert.That(lanes[step], Is.EqualTo(scalar[step]), scene + ": state bits after host step " + (step + 1));
            }
            finally
            {
                VectorPath.Enabled = saved;
            }
        }

        /// <summary>The state bits after each host step of the scene (positions and velocities, see the class summary).</summary>
        private static List<long[]> Run(string scene)
        {
            Rope rope = Build(scene);
            var chain = (ChainState)ChainField.GetValue(rope);
            var states = new List<long[]>();
            for (int step = 0; step < HostSteps; step++)
            {
                if (scene == "broken-32" && step == 20) rope.BreakSegment(11);
                rope.Step(RopeTestKit.HostStep);
                states.Add(Bits(chain));
            }
            // the scene must have moved (a scene at rest would compare nothing)
            Assert.That(rope.KineticEnergy(), Is.GreaterThan(0.0), scene + ": kinetic energy after the run (J)");
            return states;
        }

        private static long[] Bits(ChainState c)
        {
            int n = c.ParticleCount;
            var bits = new long[15 * n];
            float[][] floats = { c.PrevX, c.PrevY, c.PrevZ, c.LowX, c.LowY, c.LowZ, c.DX, c.DY, c.DZ, c.DLowX, c.DLowY, c.DLowZ };
            double[][] doubles = { c.VelX, c.VelY, c.VelZ };
            int k = 0;
            foreach (float[] a in floats)
                for (int i = 0; i < n; i++) bits[k++] = BitConverter.SingleToInt32Bits(a[i]);
            foreach (double[] a in doubles)
                for (int i = 0; i < n; i++) bits[k++] = BitConverter.DoubleToInt64Bits(a[i]);
            return bits;
        }

        private static Rope Build(string scene)
        {
            switch (scene)
            {
                case "bdf2-swing-61": return Swing(61, TimeIntegrator.Bdf2, TensionModel.TensionOnly, 1f, 1e-3f);
                case "swing-256": return Swing(256, TimeIntegrator.Bdf2, TensionModel.TensionOnly, 1f, 0f);
                case "be-load-64":
                {
                    Rope rope = Swing(64, TimeIntegrator.BackwardEuler, TensionModel.TensionOnly, 1f, 2e-3f);
                    rope.AddLoad(64, 5f);
                    return rope;
                }
                case "goal-lanyard-64":
                {
                    // issue 18's goal lanyard: default settings, pinned at both ends 1.8 m apart, sagging
                    var start = new Float3(0f, 2f, 0f);
                    var end = new Float3(1.8f, 2f, 0f);
                    var rope = new Rope(new RopeSettings { SegmentCount = 64 }, start, end);
                    rope.AddPin(0, start);
                    rope.AddPin(64, end);
                    return rope;
                }
                case "slack-tension-only-37":
                {
                    // 1 m laid over 0.5 m: every segment starts slack
                    var settings = RopeTestKit.Legacy(segments: 37, damping: 1e-3f);
                    settings.Integrator = TimeIntegrator.Bdf2;
                    var rope = new Rope(settings, Float3.Zero, new Float3(0.5f, 0f, 0f));
                    rope.AddPin(0, Float3.Zero);
                    rope.AddPin(37, new Float3(0.5f, 0f, 0f));
                    return rope;
                }
                case "bilateral-rod-bdf2-24": return Swing(24, TimeIntegrator.Bdf2, TensionModel.Bilateral, 0.9f, 1e-3f);
                case "bilateral-rod-be-19": return Swing(19, TimeIntegrator.BackwardEuler, TensionModel.Bilateral, 0.9f, 1e-3f);
                case "sphere-friction-40":
                {
                    Rope rope = Swing(40, TimeIntegrator.Bdf2, TensionModel.TensionOnly, 1f, 1e-3f);
                    RopeTestKit.AddGridSphere(rope, 0.5f);
                    return rope;
                }
                case "plane-friction-48":
                {
                    Rope rope = Swing(48, TimeIntegrator.BackwardEuler, TensionModel.TensionOnly, 1f, 0f);
                    rope.AddCollider(ColliderShape.Plane(new Float3(0f, -0.7f, 0f), new Float3(0.2f, 1f, 0f).NormalizedOr(new Float3(0f, 1f, 0f)), 0.4f));
                    return rope;
                }
                case "plastic-neck-33":
                {
                    var settings = RopeTestKit.Legacy(segments: 33);
                    settings.Integrator = TimeIntegrator.Bdf2;
                    settings.MaterialModel = MaterialModel.ElasticPlastic;
                    Rope rope = RopeTestKit.Hanging(settings, 100f, out int load);
                    rope.SetLoadState(load, rope.GetPosition(33), new Float3(0f, -6f, 0f));
                    return rope;
                }
                case "broken-32": return Swing(32, TimeIntegrator.Bdf2, TensionModel.TensionOnly, 1f, 1e-3f);
                case "one-segment":
                {
                    Rope rope = Swing(1, TimeIntegrator.Bdf2, TensionModel.TensionOnly, 1f, 1e-3f);
                    rope.AddLoad(1, 1f);
                    return rope;
                }
                case "two-segments": return Swing(2, TimeIntegrator.BackwardEuler, TensionModel.Bilateral, 1f, 1e-3f);
                default: throw new ArgumentException("unknown scene " + scene, nameof(scene));
            }
        }

        /// <summary>A 1 m rope of the legacy settings pinned at the origin and laid 30° off the vertical at stretch × 1 m.</summary>
        private static Rope Swing(int segments, TimeIntegrator integrator, TensionModel tension, float stretch, float damping)
        {
            var settings = RopeTestKit.Legacy(segments: segments, damping: damping);
            settings.Integrator = integrator;
            settings.Tension = tension;
            var rope = new Rope(settings, Float3.Zero, new Float3(0.5f * stretch, -0.8660254f * stretch, 0f));
            rope.AddPin(0, Float3.Zero);
            return rope;
        }
    }
}
