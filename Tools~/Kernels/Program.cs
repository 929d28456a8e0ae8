using System;
using System.Diagnostics;
using System.Globalization;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Kernels
{
    /// <summary>
    /// Kernel probe (issue 18 item 1). Commands:
    /// <list type="bullet">
    /// <item><c>run SCENE STEPS</c>: builds a scene of <see cref="KernelScene"/>, steps it STEPS host steps of 1/90 s and
    /// prints a hash of the state; run under callgrind twice (count.sh) for instructions per simulated second.
    /// <c>run goal-world:N K</c> / <c>run goal-step:N K</c> (<c>goal-lean:N</c>: meshes without tangents): K frames of the goal bench's window in a world of N
    /// lanyards with / without mesh fills (<see cref="GoalWorldScene"/>; goal-count.sh counts them).</item>
    /// <item><c>hash [STEPS]</c>: the state hash of every scene after STEPS (default 900) steps, for bit-identity checks.</item>
    /// <item><c>mesh-hash [ROPES] [FRAMES]</c>: the hash of every tube vertex and index the goal world (default 10 ropes) fills
    /// in FRAMES (default the bench's window) frames, for bit-identity checks of the mesh.</item>
    /// <item><c>time [--quick]</c>: wall-clock ns per Gauss–Seidel projection and per exact segment-iteration, 16 … 10 000
    /// segments (whole step at 8 substeps × 1 iteration, and marginal: 10 against 2 iterations at 1 substep); the exact
    /// solve on the fresh and the resting hanging rope, with its Newton iterations per substep, linear solves per iteration
    /// and ns per segment-solve performed (<see cref="KernelTimer"/>).</item>
    /// </list>
    /// With the environment variable <c>KERNELS_VECTORS=off</c> every command runs the scalar paths
    /// (<see cref="VectorPath.Enabled"/> false, as on a runtime whose <c>Vector.IsHardwareAccelerated</c> is false: the
    /// same bits, other code).
    /// </summary>
    public static class Program
    {
        public static int Main(string[] args)
        {
            if (Environment.GetEnvironmentVariable("KERNELS_VECTORS") == "off") VectorPath.Enabled = false;
            if (args.Length == 3 && args[0] == "run" && GoalWorldScene.Is(args[1]))
                return GoalWorldScene.Run(args[1], int.Parse(args[2], CultureInfo.InvariantCulture));
            if (args.Length == 3 && args[0] == "run")
            {
                RopeSimulation simulation = KernelScene.Simulation(args[1]);
                Rope rope = simulation != null ? simulation.Rope : KernelScene.Build(args[1]);
                int steps = int.Parse(args[2], CultureInfo.InvariantCulture);
                for (int i = 0; i < steps; i++) Step(simulation, rope);
                Console.WriteLine(args[1] + " " + steps + " steps: " + Hash(rope).ToString("x16", CultureInfo.InvariantCulture));
                return 0;
            }
            if (args.Length >= 1 && args[0] == "hash")
            {
                int steps = args.Length > 1 ? int.Parse(args[1], CultureInfo.InvariantCulture) : 900;
                foreach (string name in KernelScene.Names)
                {
                    RopeSimulation simulation = KernelScene.Simulation(name);
                    Rope rope = simulation != null ? simulation.Rope : KernelScene.Build(name);
                    for (int i = 0; i < steps; i++) Step(simulation, rope);
                    Console.WriteLine(name.PadRight(24) + Hash(rope).ToString("x16", CultureInfo.InvariantCulture));
                }
                return 0;
            }
            if (args.Length >= 1 && args[0] == "mesh-hash")
                return GoalWorldScene.MeshHash(args.Length > 1 ? int.Parse(args[1], CultureInfo.InvariantCulture) : 10,
                    args.Length > 2 ? int.Parse(args[2], CultureInfo.InvariantCulture) : HookeRope.Bench.GoalScene.WindowFrames);
            if (args.Length >= 1 && args[0] == "time") return KernelTimer.Execute(args.Length > 1 && args[1] == "--quick");
            Console.Error.WriteLine("usage: run SCENE STEPS | hash [STEPS] | mesh-hash [ROPES] [FRAMES] | time [--quick]   (scenes: " + string.Join(", ", KernelScene.Names) + ", goal-world:N, goal-lean:N, goal-step:N)");
            return 2;
        }

        /// <summary>One host step: through the simulation when the scene has one (radius model, read-outs), else the rope's alone.</summary>
        private static void Step(RopeSimulation simulation, Rope rope)
        {
            if (simulation != null) simulation.Step(KernelScene.HostStep);
            else rope.Step(KernelScene.HostStep);
        }

        /// <summary>FNV-1a over the bits of every position, velocity and tension.</summary>
        internal static ulong Hash(Rope rope)
        {
            ulong h = 14695981039346656037UL;
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                Float3 v = rope.GetVelocity(i);
                h = Mix(h, rope.PositionX[i]); h = Mix(h, rope.PositionY[i]); h = Mix(h, rope.PositionZ[i]);
                h = Mix(h, v.X); h = Mix(h, v.Y); h = Mix(h, v.Z);
            }
            for (int j = 0; j < rope.SegmentCount; j++) { h = Mix(h, rope.Tensions[j]); h = Mix(h, rope.PeakTensions[j]); h = Mix(h, rope.MeanTensions[j]); }
            return h;
        }

        private static ulong Mix(ulong h, float value)
        {
            uint bits = (uint)BitConverter.SingleToInt32Bits(value);
            for (int b = 0; b < 4; b++) { h ^= (bits >> (8 * b)) & 0xff; h *= 1099511628211UL; }
            return h;
        }
    }
}
