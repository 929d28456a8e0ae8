using System;
using HookeRope.Solver;

namespace HookeRope.Editor
{
    /// <summary>
    /// A-priori estimate of how far the solver will leave the rope over-stretched (relative error of the static
    /// elongation), from the settings alone, for the inspector warning. It is a convergence estimate, not a
    /// simulation: Gauss–Seidel sweeps on a chain of n segments reduce the error by about cos²(π/(n+1)) per sweep
    /// in the stiff limit, slowed further by the ratio of the end load to a particle's mass; soft segments
    /// (compliance large against a substep) converge faster. The exact chain solve is exact per iteration.
    /// </summary>
    public static class StretchErrorEstimate
    {
        /// <summary>Relative error above which the inspector warns (5 %).</summary>
        public const double WarningThreshold = 0.05;

        /// <summary>
        /// Predicted relative stretch error (dimensionless, 0 … 1) for a rope of <paramref name="segments"/>
        /// segments of total rest length <paramref name="restLength"/> (m), axial stiffness
        /// <paramref name="axialStiffness"/> (N), mass per metre <paramref name="linearDensity"/> (kg/m), an end
        /// load of <paramref name="endMass"/> (kg, 0 = none), stepped every <paramref name="hostDeltaTime"/> (s)
        /// with the given substeps, iterations and solver.
        /// </summary>
        public static double Predict(int segments, float restLength, float axialStiffness, float linearDensity, float endMass,
            float hostDeltaTime, int substeps, int iterations, ConstraintSolverKind solver)
        {
            if (segments < 1) throw new ArgumentOutOfRangeException(nameof(segments), segments, "segments must be in [1, +inf)");
            if (!(restLength > 0f)) throw new ArgumentOutOfRangeException(nameof(restLength), restLength, "restLength must be in (0, +inf) m");
            if (!(axialStiffness > 0f)) throw new ArgumentOutOfRangeException(nameof(axialStiffness), axialStiffness, "axialStiffness must be in (0, +inf) N");
            if (!(linearDensity > 0f)) throw new ArgumentOutOfRangeException(nameof(linearDensity), linearDensity, "linearDensity must be in (0, +inf) kg/m");
            if (!(endMass >= 0f)) throw new ArgumentOutOfRangeException(nameof(endMass), endMass, "endMass must be in [0, +inf) kg");
            if (!(hostDeltaTime > 0f)) throw new ArgumentOutOfRangeException(nameof(hostDeltaTime), hostDeltaTime, "hostDeltaTime must be in (0, +inf) s");
            if (substeps < 1) throw new ArgumentOutOfRangeException(nameof(substeps), substeps, "substeps must be in [1, +inf)");
            if (iterations < 1) throw new ArgumentOutOfRangeException(nameof(iterations), iterations, "iterations must be in [1, +inf)");
            if (solver == ConstraintSolverKind.ExactChain) return 0.0;

            double segmentLength = (double)restLength / segments;
            double particleMass = linearDensity * segmentLength;
            double h = (double)hostDeltaTime / substeps;
            // Stiffness against one substep: (w_a + w_b) / α̃ with α̃ = L_seg / (E·A·h²).
            double stiffness = 2.0 / particleMass * h * h * axialStiffness / segmentLength;
            double softness = stiffness / (1.0 + stiffness);
            double sweepGain = Math.Pow(Math.Sin(Math.PI / (segments + 1)), 2.0);
            double massRatio = endMass / particleMass;
            double gain = sweepGain / (1.0 + massRatio / segments);
            double sweeps = (double)substeps * iterations;
            return softness * Math.Exp(-gain * sweeps);
        }
    }
}
