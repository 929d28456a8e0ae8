using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;
using HookeRope.World;

namespace HookeRope.Bench
{
    /// <summary>
    /// The scene of issue 18's goal: lanyards at the default settings (exact chain, 8 substeps × 1 iteration, the
    /// default radius model), each pinned at both ends 1.8 m apart and sagging, with a tube mesh of
    /// <see cref="MeshSides"/> sides filled from the rope after every step, all in one <see cref="RopeWorld"/>.
    /// </summary>
    internal static class GoalScene
    {
        /// <summary>Radial segments of the tube mesh (16 in the goal).</summary>
        public const int MeshSides = 16;

        /// <summary>Host step of one VR frame, s.</summary>
        public const float Frame = 1f / 90f;

        /// <summary>
        /// A world of <paramref name="ropes"/> lanyards × <paramref name="segments"/> on <paramref name="workers"/> workers,
        /// warmed up by 20 frames; <paramref name="adaptiveRings"/> false draws 4 rings per segment (the mesh before issue 18).
        /// </summary>
        public static RopeWorld Build(int ropes, int segments, int workers, bool adaptiveRings = true)
        {
            var world = new RopeWorld(workers);
            for (int r = 0; r < ropes; r++)
            {
                var settings = new RopeSettings { SegmentCount = segments };
                var start = new Float3(r * 0.5f, 2f, 0f);
                var end = new Float3(r * 0.5f + 1.8f, 2f, 0f);
                var simulation = new RopeSimulation(settings, start, end, new RadiusSettings());
                simulation.MeshSettings.RadialSegments = MeshSides;
                simulation.MeshSettings.AdaptiveRings = adaptiveRings;
                simulation.Rope.AddPin(0, start);
                simulation.Rope.AddPin(segments, end);
                world.EnableMesh(world.Add(simulation));
            }
            for (int i = 0; i < WarmUpFrames; i++) world.StepAndFillMeshes(Frame);
            return world;
        }

        /// <summary>
        /// Frames stepped by <see cref="Build"/> before a measurement. The lanyards start straight and drop, so the ring
        /// budget of their mesh follows the drop's waves (one lanyard, 16 sides: 1 411 vertices in frames 1–5, 2 227 from
        /// 14, 4 403 from 45, 5 491 in frames 204–320, back to 2 771 at 794 and 2 227 at 1 626): a row's vertex count
        /// depends on the frames it measured (<see cref="GoalRow.LastFrame"/>), not on where its ropes sit.
        /// </summary>
        public const int WarmUpFrames = 20;

        /// <summary>Substeps of the default settings.</summary>
        public static int Substeps => new RopeSettings().Substeps;
    }
}
