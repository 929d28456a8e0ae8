#if HOOKEROPE_SOLVER
using HookeRope.Lab.Scenarios;

namespace HookeRope.Lab.Simulation
{
    /// <summary>Captures the tube mesh of a rope (radius branch's TubeMeshBuilder).</summary>
    public static class MeshCapture
    {
        /// <summary>The tube mesh at time t, or null when the mesh builder is not available.</summary>
        public static MeshSnapshot Capture(RopeSetup setup, Scenario s, double t)
        {
            // TODO(radius): build with HookeRope.Geometry.TubeMeshBuilder once merged.
            return null;
        }
    }
}
#endif
