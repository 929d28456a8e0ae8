using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope.Bench
{
    /// <summary>
    /// <c>mesh [--quick] [--instructions] [--world]</c>: the cost of the tube mesh alone (issue 18 item 2), per vertex and per
    /// rope, on the goal scene's lanyard (64 segments, default settings and radius model, pinned 1.8 m apart and
    /// sagging) and on a 200-segment helix with one break (the shape of the older radius-and-mesh.md table), at 8, 16 and
    /// 32 sides. Modes: <c>moving</c> (the rope is stepped between fills, as in the goal scene: positions and radii
    /// change; only the fill is timed), <c>full</c> (two recorded poses and two radius scales alternate: every fill
    /// recomputes everything, radius work included), <c>positions</c> (the poses alternate, radii unchanged: Unity's
    /// interpolated frames between physics steps), <c>radii</c> (the same pose, the radius scales alternate) and
    /// <c>unchanged</c> (the same pose and radii again); then the goal world's fills, with and without tangents (<c>--world</c>:
    /// only these). <c>meshframes …</c> is the workload callgrind counts
    /// (<see cref="MeshInstructions"/>). Timings are printed, never asserted.
    /// </summary>
    internal static class MeshBench
    {
        /// <summary>The ring layouts a row can ask for.</summary>
        public enum Layout
        {
            /// <summary>What RopeSimulation does by default (adaptive rings since issue 18).</summary>
            Default,
            /// <summary>Adaptive rings off: RingsPerSegment = 4 in every segment (and the Zone neck's stations), the layout before issue 18.</summary>
            Uniform4,
        }

        /// <summary>How the fills of a row differ from each other.</summary>
        public enum Mode
        {
            /// <summary>The rope is stepped (1/90 s) before every fill.</summary>
            Moving,
            /// <summary>Two recorded poses and two radius scales alternate: everything changes.</summary>
            Full,
            /// <summary>Two recorded poses alternate (caller positions), radii unchanged.</summary>
            Positions,
            /// <summary>The same pose, two radius scales alternate.</summary>
            Radii,
            /// <summary>The same pose and radii every fill.</summary>
            Unchanged,
        }

        /// <summary>The scenes.</summary>
        public enum Scene
        {
            /// <summary>The goal scene's lanyard: 64 segments, both ends pinned, sagging.</summary>
            Lanyard,
            /// <summary>A 200-segment helix (radius 0.3 m) with one broken segment, not stepped (positions set).</summary>
            Helix,
        }

        /// <summary>A scene's simulation with its mesh buffers, ready to fill.</summary>
        internal sealed class Rig
        {
            public RopeSimulation Simulation;
            public TubeVertex[] Vertices;
            public int[] Indices;
            public float[][] PoseX = new float[2][], PoseY = new float[2][], PoseZ = new float[2][];
            public int Fills;

            /// <summary>One fill in <paramref name="mode"/> (the step of Moving is done here, before the fill, and not by the caller's timer when <paramref name="timer"/> is given).</summary>
            public int Fill(Mode mode, Stopwatch timer)
            {
                if (mode == Mode.Moving) Simulation.Step(GoalScene.Frame);
                int pose = mode == Mode.Positions || mode == Mode.Full ? Fills & 1 : 0;
                float scale = (mode == Mode.Radii || mode == Mode.Full) && (Fills & 1) == 1 ? 0.999f : 1f;
                timer?.Start();
                int vertices = mode == Mode.Moving
                    ? Simulation.FillMesh(Vertices, Indices).VertexCount
                    : Simulation.FillMesh(PoseX[pose], PoseY[pose], PoseZ[pose], Vertices, Indices, scale).VertexCount;
                timer?.Stop();
                Fills++;
                return vertices;
            }
        }

        /// <summary>Builds <paramref name="scene"/> with <paramref name="sides"/> radial segments and <paramref name="layout"/>, warmed up.</summary>
        public static Rig Build(Scene scene, int sides, Layout layout)
        {
            var rig = new Rig();
            RopeSimulation sim;
            if (scene == Scene.Lanyard)
            {
                var settings = new RopeSettings { SegmentCount = 64 };
                var start = new Float3(0f, 2f, 0f);
                var end = new Float3(1.8f, 2f, 0f);
                sim = new RopeSimulation(settings, start, end, new RadiusSettings());
                sim.Rope.AddPin(0, start);
                sim.Rope.AddPin(64, end);
            }
            else
            {
                const int n = 200;
                var settings = new RopeSettings { SegmentCount = n, RestLength = 0.5f * n * 0.3f * 1.02f };
                sim = new RopeSimulation(settings, Float3.Zero, new Float3(1f, 0f, 0f), new RadiusSettings());
                for (int i = 0; i <= n; i++)
                {
                    float angle = 0.5f * i;
                    sim.Rope.SetPosition(i, new Float3(0.3f * MathF.Cos(angle), 0.3f * MathF.Sin(angle), 0.05f * angle));
                }
                sim.Rope.BreakSegment(n / 2);
                sim.UpdateRadii();
            }
            sim.MeshSettings.RadialSegments = sides;
            Configure(sim, layout);
            rig.Simulation = sim;
            for (int f = 0; f < 2; f++)
            {
                if (scene == Scene.Lanyard)
                    for (int i = 0; i < 20; i++) sim.Step(GoalScene.Frame);
                int p = sim.Rope.ParticleCount;
                rig.PoseX[f] = sim.Rope.PositionX.ToArray();
                rig.PoseY[f] = sim.Rope.PositionY.ToArray();
                rig.PoseZ[f] = sim.Rope.PositionZ.ToArray();
                if (scene == Scene.Helix)
                    for (int i = 0; i < p; i++) rig.PoseZ[f][i] += 1e-4f * f * MathF.Sin(0.3f * i);
            }
            rig.Vertices = new TubeVertex[sim.GetVertexCount() * 2];
            rig.Indices = new int[sim.GetIndexCount() * 2];
            return rig;
        }

        /// <summary>Applies <paramref name="layout"/> to the mesh settings.</summary>
        public static void Configure(RopeSimulation sim, Layout layout)
        {
            if (layout != Layout.Uniform4) return;
            sim.MeshSettings.AdaptiveRings = false;
            sim.MeshSettings.RingsPerSegment = 4;
        }

        /// <summary>
        /// Fastest and median µs per fill over <paramref name="rounds"/> rounds of <paramref name="fills"/> fills (after a
        /// warm-up), and the vertices of the last fill. On a shared machine the fastest round is the one least disturbed
        /// by other processes.
        /// </summary>
        public static (double Best, double Median, int Vertices) Time(Rig rig, Mode mode, int fills, int rounds)
        {
            int vertices = 0;
            // warm-up long enough for the tiered JIT to install optimised code (≥ 0.4 s and 300 fills)
            var warm = Stopwatch.StartNew();
            for (int i = 0; i < 300 || warm.ElapsedMilliseconds < 400; i++) vertices = rig.Fill(mode, null);
            var samples = new List<double>();
            var timer = new Stopwatch();
            for (int r = 0; r < rounds; r++)
            {
                timer.Reset();
                for (int i = 0; i < fills; i++) vertices = rig.Fill(mode, timer);
                samples.Add(timer.Elapsed.TotalMilliseconds * 1e3 / fills);
            }
            samples.Sort();
            return (samples[0], samples[samples.Count / 2], vertices);
        }

        /// <summary>Runs the command; returns the process exit code.</summary>
        public static int Execute(string[] args)
        {
            bool quick = Array.IndexOf(args, "--quick") >= 0, instructions = Array.IndexOf(args, "--instructions") >= 0;
            bool worldOnly = Array.IndexOf(args, "--world") >= 0;
            var c = CultureInfo.InvariantCulture;
            Console.WriteLine($"HookeRope bench · mesh  {Environment.ProcessorCount} logical processors, load average {GoalBench.LoadAverage().ToString("F2", c)}, " +
                              $"{System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription}");
            Console.WriteLine("one fill = RopeSimulation.FillMesh of one rope; moving = stepped before each fill (fill timed alone), full = poses and radius scales alternate,");
            Console.WriteLine("positions = poses alternate (same radii), radii = radius scales alternate (same pose), unchanged = same pose and radii");
            Console.WriteLine();
            if (!worldOnly) PrintRopeTable(quick, instructions);
            Console.WriteLine("goal scene (100 lanyards x 64 segments, 16 sides): RopeWorld.FillMeshes alone per 1/90 s frame (the step before it not timed)");
            string goalHeader = string.Format(c, "{0,-48} {1,7} {2,11} {3,10} {4,10} {5,10}", "phase", "workers", "verts/rope", "ms/frame", "min ms", "ns/vertex");
            Console.WriteLine(goalHeader);
            Console.WriteLine(new string('-', goalHeader.Length));
            foreach (var (adaptive, tangents) in new[] { (true, true), (true, false), (false, true) })
                foreach (int settle in new[] { 0, 1800 })
                    foreach (int workers in new[] { 1, 2 })
                    {
                        var (ms, min, vertices) = GoalMesh(workers, settle, adaptive, quick ? 0.5 : 1.5, tangents);
                        string phase = (adaptive ? "adaptive" : "4 rings/segment") + (tangents ? "" : ", no tangents") + (settle == 0 ? ", frames 20+ (swinging)" : ", after 20 s (settled)");
                        Console.WriteLine(string.Format(c, "{0,-48} {1,7} {2,11:F0} {3,10:F3} {4,10:F3} {5,10:F2}", phase, workers, vertices, ms, min, ms * 1e6 / (100 * vertices)));
                    }
            return 0;
        }

        /// <summary>The table of single-rope fills (every scene, layout, side count and mode).</summary>
        private static void PrintRopeTable(bool quick, bool instructions)
        {
            var c = CultureInfo.InvariantCulture;
            string header = string.Format(c, "{0,-8} {1,-9} {2,5} {3,-10} {4,9} {5,11} {6,11} {7,10} {8,13}", "scene", "layout", "sides", "mode", "vertices", "best µs", "median µs", "ns/vertex", "instr/vertex");
            Console.WriteLine(header);
            Console.WriteLine(new string('-', header.Length));
            int fills = quick ? 50 : 100, rounds = quick ? 9 : 25;
            // one pass over every mode first, so the first rows do not run while the tiered JIT still compiles
            foreach (Layout layout in Layouts())
                foreach (Mode mode in new[] { Mode.Moving, Mode.Full, Mode.Positions, Mode.Radii, Mode.Unchanged })
                {
                    var warmRig = Build(Scene.Lanyard, 16, layout);
                    for (int i = 0; i < 2000; i++) warmRig.Fill(mode, null);
                }
            foreach (Scene scene in new[] { Scene.Lanyard, Scene.Helix })
                foreach (Layout layout in Layouts())
                    foreach (int sides in new[] { 8, 16, 32 })
                        foreach (Mode mode in new[] { Mode.Moving, Mode.Full, Mode.Positions, Mode.Radii, Mode.Unchanged })
                        {
                            if (scene == Scene.Helix && mode == Mode.Moving) continue;
                            var rig = Build(scene, sides, layout);
                            var (us, median, vertices) = Time(rig, mode, fills, rounds);
                            string counted = "-";
                            if (instructions && mode == Mode.Full && (sides == 8 || sides == 16))
                            {
                                double perVertex = MeshInstructions.PerVertex(scene, sides, layout, mode, vertices, m => Console.Error.WriteLine(m));
                                if (perVertex > 0) counted = perVertex.ToString("F1", c);
                            }
                            Console.WriteLine(string.Format(c, "{0,-8} {1,-9} {2,5} {3,-10} {4,9} {5,11:F2} {6,11:F2} {7,10:F2} {8,13}",
                                scene, layout, sides, mode, vertices, us, median, us * 1e3 / Math.Max(1, vertices), counted));
                        }
            Console.WriteLine();
            Console.WriteLine("ns/vertex = best µs per fill / vertices written (fastest round: the least disturbed on a shared machine); compare instr/vertex for ratios.");
            Console.WriteLine();
        }

        /// <summary>Median and fastest ms of RopeWorld.FillMeshes per frame on the goal scene (with or without <paramref name="tangents"/>), and the mean vertices per rope.</summary>
        public static (double Ms, double Min, double Vertices) GoalMesh(int workers, int settleFrames, bool adaptive, double seconds, bool tangents = true)
        {
            using (var world = GoalScene.Build(100, 64, workers, adaptive, tangents: tangents))
            {
                for (int i = 0; i < settleFrames; i++) world.StepAndFillMeshes(GoalScene.Frame);
                var samples = new List<double>();
                var watch = new Stopwatch();
                var total = Stopwatch.StartNew();
                while (samples.Count < 15 || total.Elapsed.TotalSeconds < seconds)
                {
                    world.Step(GoalScene.Frame);
                    watch.Restart();
                    world.FillMeshes();
                    watch.Stop();
                    samples.Add(watch.Elapsed.TotalMilliseconds);
                    if (samples.Count >= 2000) break;
                }
                samples.Sort();
                return (samples[samples.Count / 2], samples[0], GoalBench.MeanVertices(world));
            }
        }

        /// <summary>The layouts compared.</summary>
        public static Layout[] Layouts() => new[] { Layout.Default, Layout.Uniform4 };

        /// <summary><c>meshframes scene sides layout mode fills [meshOff]</c>: what callgrind runs (see <see cref="MeshInstructions"/>).</summary>
        public static int Frames(string[] args)
        {
            var scene = (Scene)Enum.Parse(typeof(Scene), args[1]);
            int sides = int.Parse(args[2], CultureInfo.InvariantCulture);
            var layout = (Layout)Enum.Parse(typeof(Layout), args[3]);
            var mode = (Mode)Enum.Parse(typeof(Mode), args[4]);
            int fills = int.Parse(args[5], CultureInfo.InvariantCulture);
            bool meshOff = args.Length > 6 && args[6] == "stepOnly";
            var rig = Build(scene, sides, layout);
            for (int i = 0; i < fills; i++)
            {
                if (meshOff) rig.Simulation.Step(GoalScene.Frame);
                else rig.Fill(mode, null);
            }
            return 0;
        }
    }
}
