using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>The goal scene's lanyard for the mesh tests: pinned at both ends 2 m up, released from straight.</summary>
    internal static class GoalLanyard
    {
        /// <summary>
        /// A rope of <paramref name="settings"/> from (x, 2, 0) to (x + span, 2, 0) in metres, pinned at both ends, with
        /// default radius settings; the caller steps it.
        /// </summary>
        public static RopeSimulation Pinned(RopeSettings settings, float x, float span)
        {
            var start = new Float3(x, 2f, 0f);
            var end = new Float3(x + span, 2f, 0f);
            var simulation = new RopeSimulation(settings, start, end, new RadiusSettings());
            simulation.Rope.AddPin(0, start);
            simulation.Rope.AddPin(settings.SegmentCount, end);
            return simulation;
        }
    }
}
