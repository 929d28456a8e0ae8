using HookeRope.Geometry;
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
        /// warmed up by <paramref name="warmUpFrames"/> frames (<see cref="WarmUpFrames"/> for a measurement of the window);
        /// <paramref name="adaptiveRings"/> false draws 4 rings per segment (the mesh before issue 18);
        /// <paramref name="ringTolerance"/> is the meshes' <see cref="HookeRope.Geometry.TubeMeshSettings.RingTolerance"/>
        /// (1, the default, in the goal); a <paramref name="detailDistance"/> above 0 scales it by each rope's distance to
        /// <see cref="Viewer"/> before every warm-up frame (<see cref="ApplyViewDetail"/>; 0, off, in the goal);
        /// <paramref name="tangents"/> false fills the meshes without tangents (<see cref="RopeMeshSlot.Tangents"/>: 32-byte
        /// vertices; on, 48 bytes, in the goal).
        /// </summary>
        public static RopeWorld Build(int ropes, int segments, int workers, bool adaptiveRings = true, int warmUpFrames = BuildFrames, float ringTolerance = 1f,
            float detailDistance = 0f, bool tangents = true)
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
                simulation.MeshSettings.RingTolerance = ringTolerance;
                simulation.Rope.AddPin(0, start);
                simulation.Rope.AddPin(segments, end);
                world.EnableMesh(world.Add(simulation)).Tangents = tangents;
            }
            for (int i = 0; i < warmUpFrames; i++)
            {
                if (detailDistance > 0f) ApplyViewDetail(world, ringTolerance, detailDistance);
                world.StepAndFillMeshes(Frame);
            }
            return world;
        }

        /// <summary>
        /// Frames a measurement steps before its window (frames 1 … 44, <c>Build(…, warmUpFrames: WarmUpFrames)</c>). The lanyards start straight and
        /// drop, and the ring budget of their mesh follows the drop's waves (one lanyard, 16 sides: 1 411 vertices in
        /// frames 1–5, 2 227 from 14, 2 771 from 29, 3 315 from 32, 4 403 from 45 to 203, 5 491 in frames 204–320, 2 771
        /// at 794, 2 227 from 1 626; the same in worlds of 1 … 500 lanyards): the warm-up ends where the budget settles, so
        /// every row measures <see cref="WindowFrames"/> frames at 4 403 vertices per lanyard.
        /// </summary>
        public const int WarmUpFrames = 44;

        /// <summary>Frames <see cref="Build"/> steps unless told otherwise (20: the mesh bench's "frames 20+" world).</summary>
        public const int BuildFrames = 20;

        /// <summary>
        /// Frames every measurement times, frames <see cref="WarmUpFrames"/> + 1 … <see cref="WarmUpFrames"/> +
        /// <see cref="WindowFrames"/> (45 … 74) of a freshly built world: the bench's rows and the probe's instruction
        /// count (Tools~/Kernels, scene <c>goal-world:N</c>) cover the same frames of the same scene.
        /// </summary>
        public const int WindowFrames = 30;

        /// <summary>The window as text, e.g. "45-74" (a baseline row compares only with a row of the same window).</summary>
        public static string Window => (WarmUpFrames + 1) + "-" + (WarmUpFrames + WindowFrames);

        /// <summary>
        /// Where the view-distance rows stand (m): a viewer at eye height 1 m in front of the first lanyard (the lanyards
        /// hang in a row along +x, 0.5 m apart: the first about 1 m away, the last about 50 m).
        /// </summary>
        public static readonly Float3 Viewer = new Float3(0.9f, 1.6f, -1f);

        /// <summary>
        /// Sets each rope's side count and ring tolerance from its distance to <see cref="Viewer"/> (<see cref="ViewDetail"/>:
        /// the box around its particles; <see cref="MeshSides"/> and <paramref name="ringTolerance"/> up to
        /// <paramref name="detailDistance"/>, the tolerance growing beyond it, half the sides from 4.4 times as far), as
        /// RopeMeshRenderer does each frame with a View Point.
        /// </summary>
        public static void ApplyViewDetail(RopeWorld world, float ringTolerance, float detailDistance)
        {
            for (int i = 0; i < world.Count; i++)
            {
                var simulation = world.GetRope(i);
                var rope = simulation.Rope;
                var viewer = Viewer - rope.Origin;
                float distance = ViewDetail.DistanceToBox(rope.PositionX, rope.PositionY, rope.PositionZ, rope.ParticleCount, viewer);
                ViewDetail.Choose(MeshSides, ringTolerance, detailDistance, distance, simulation.MeshSettings.RadialSegments, false,
                    out int sides, out float tolerance);
                simulation.MeshSettings.RadialSegments = sides;
                simulation.MeshSettings.RingTolerance = tolerance;
            }
        }

        /// <summary>Substeps of the default settings.</summary>
        public static int Substeps => new RopeSettings().Substeps;
    }
}
