using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope.Tests.Core.Fracture
{
    /// <summary>
    /// The lab's fracture cord: 1 m, 21 segments, radius 1 cm, E·A 1 kN, no gravity, pinned at the origin and by
    /// <see cref="EndPin"/> at x = 1 m, necking in a zone at mid-length and breaking at 50 % strain.
    /// </summary>
    internal static class FractureCord
    {
        /// <summary>Rope radius in metres.</summary>
        public const float Radius = 0.01f;

        /// <summary>Particle index of the pulled end.</summary>
        public const int EndParticle = 21;

        /// <summary>The cord at rest length, its end pinned at x = 1 m; <paramref name="endPin"/> is that pin's handle.</summary>
        public static RopeSimulation Build(TubeMeshSettings mesh, out int endPin)
        {
            var settings = new RopeSettings
            {
                RestLength = 1f, SegmentCount = 21, Radius = Radius, AxialStiffness = 1000f, Density = 1100f, Gravity = Float3.Zero,
                Substeps = 4, Iterations = 1, Damping = 0.01f, Solver = ConstraintSolverKind.ExactChain,
            };
            var radius = new RadiusSettings
            {
                PoissonRatio = 0.5f, Necking = true, NeckMode = NeckMode.Zone, NeckRadiusFraction = 0.85f, DefectPosition = 0.5f,
                Fracture = true, BreakStrain = 0.5f,
            };
            var rope = new Rope(settings, Float3.Zero, new Float3(1f, 0f, 0f));
            rope.AddPin(0, Float3.Zero);
            endPin = rope.AddPin(EndParticle, new Float3(1f, 0f, 0f));
            return new RopeSimulation(rope, radius, mesh);
        }
    }
}
