using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Bench
{
    /// <summary>
    /// The rope values the benchmarks were measured with (the core's pre-issue-12 defaults), stated explicitly so
    /// that the timings stay comparable when <see cref="RopeSettings"/> takes the parameter table's defaults.
    /// </summary>
    internal static class LegacySettings
    {
        /// <summary>Substeps per host step.</summary>
        public const int Substeps = 8;

        /// <summary>A rope of the given rest length (m), segment count and solver; R 5 mm, E 1 GPa, ρ 1140 kg/m³, β 0 s, 8 substeps, 1 iteration.</summary>
        public static RopeSettings Create(float restLength, int segments, ConstraintSolverKind solver) => new RopeSettings
        {
            RestLength = restLength,
            SegmentCount = segments,
            Radius = 0.005f,
            YoungsModulus = 1e9f,
            Density = 1140f,
            Damping = 0f,
            Gravity = new Float3(0f, -9.81f, 0f),
            Substeps = Substeps,
            Iterations = 1,
            Solver = solver,
            Tension = TensionModel.TensionOnly,
        };
    }
}
