using System;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// One extreme case of the stability matrix (the solver stability tests): a rope of
    /// <see cref="RestLength"/> hanging from a rigid pin at the world origin, optionally with a load at the
    /// bottom, laid straight down stretched by <see cref="Stretch"/> (or with every particle on the pin
    /// when <see cref="Coincident"/>), and optionally an anchor teleport. <see cref="Run"/> steps it and
    /// measures finiteness, energy growth and recovery. States every rope value explicitly (the pre-issue-12
    /// core defaults where the matrix does not vary it).
    /// </summary>
    internal sealed class StabilityCase
    {
        /// <summary>Young's modulus in Pa (1e6 … 2e11 in the matrix; +inf allowed).</summary>
        public float YoungsModulus { get; set; } = 1e9f;
        /// <summary>Load mass divided by one rope particle's mass (1 … 1e6); 0 = no load.</summary>
        public double MassRatio { get; set; } = 1.0;
        /// <summary>Host step in seconds (1/1000 … 1/30).</summary>
        public float HostDeltaTime { get; set; } = 1f / 90f;
        /// <summary>Segment count (2 … 10000).</summary>
        public int SegmentCount { get; set; } = 16;
        /// <summary>Initial length over rest length (1 = unstretched, up to 10).</summary>
        public float Stretch { get; set; } = 1f;
        /// <summary>Distance in metres the anchor jumps along +X in one host step after the first second (0 = none).</summary>
        public float TeleportDistance { get; set; }
        /// <summary>Start with every particle on the anchor point.</summary>
        public bool Coincident { get; set; }
        /// <summary>Time integrator (default: the package default).</summary>
        public TimeIntegrator Integrator { get; set; } = RopeSettings.DefaultIntegrator;
        /// <summary>Tension model.</summary>
        public TensionModel Tension { get; set; } = TensionModel.TensionOnly;
        /// <summary>Constraint solver.</summary>
        public ConstraintSolverKind Solver { get; set; } = ConstraintSolverKind.ExactChain;
        /// <summary>Substeps per host step.</summary>
        public int Substeps { get; set; } = 8;
        /// <summary>Rest length in metres.</summary>
        public float RestLength { get; set; } = 1f;
        /// <summary>Rope radius in metres.</summary>
        public float Radius { get; set; } = 0.005f;
        /// <summary>Material density in kg/m³.</summary>
        public float Density { get; set; } = 1140f;

        /// <summary>Builds the rope of this case (the anchor is pin 0).</summary>
        public Rope Build()
        {
            var settings = new RopeSettings
            {
                RestLength = RestLength,
                SegmentCount = SegmentCount,
                Radius = Radius,
                YoungsModulus = YoungsModulus,
                Density = Density,
                Damping = 0f,
                Gravity = new Float3(0f, -9.81f, 0f),
                Iterations = 1,
                Tension = Tension,
                Integrator = Integrator,
                Solver = Solver,
                Substeps = Substeps,
            };
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -RestLength * Stretch, 0f));
            rope.AddPin(0, Float3.Zero);
            if (MassRatio > 0.0)
            {
                float particleMass = settings.LinearDensity * RestLength / SegmentCount;
                rope.AddLoad(rope.ParticleCount - 1, (float)(particleMass * MassRatio));
            }
            if (Coincident)
                for (int i = 1; i < rope.ParticleCount; i++) rope.SetPosition(i, Float3.Zero);
            return rope;
        }

        /// <summary>Steps the case for <paramref name="seconds"/> and reports what happened.</summary>
        public StabilityResult Run(double seconds)
        {
            Rope rope = Build();
            int steps = (int)Math.Ceiling(seconds / HostDeltaTime);
            int teleportStep = TeleportDistance != 0f ? (int)Math.Ceiling(1.0 / HostDeltaTime) : -1;
            var result = new StabilityResult { Finite = true, InitialEnergy = RopeTestKit.TotalEnergy(rope, upper: true), StaticElongation = StaticElongation(rope) };
            double ceiling = result.InitialEnergy;
            for (int s = 0; s < steps; s++)
            {
                if (s == teleportStep) rope.SetPinTarget(0, new Float3(TeleportDistance, 0f, 0f));
                StepReport report = rope.Step(HostDeltaTime);
                // the total energy (kinetic + gravitational + elastic) against the work put in (the initial total, or the
                // total right after the teleport); the elastic part is the least any state within float32 round-off of this
                // one stores (now) and the most (the ceiling), so stiff segments' position round-off is not read as a gain
                double energy = RopeTestKit.TotalEnergy(rope, upper: false);
                if (s == teleportStep) ceiling = Math.Max(ceiling, RopeTestKit.TotalEnergy(rope, upper: true));
                result.LargestEnergyGain = Math.Max(result.LargestEnergyGain, energy - ceiling);
                result.LargestKineticEnergy = Math.Max(result.LargestKineticEnergy, rope.KineticEnergy());
                result.FinalResidual = report.Residual;
                result.ViolentSubsteps += report.ViolentSubsteps;
                result.UnconvergedSubsteps += report.UnconvergedSubsteps;
                if (!IsFinite(rope) || double.IsNaN(energy) || double.IsInfinity(energy)) { result.Finite = false; break; }
            }
            result.EnergyCeiling = ceiling;
            result.FinalKineticEnergy = rope.KineticEnergy();
            Float3 anchor = rope.GetPinTarget(0);
            for (int i = 0; i < rope.ParticleCount; i++)
                result.FarthestFromAnchor = Math.Max(result.FarthestFromAnchor, (rope.GetPosition(i) - anchor).Length);
            result.TopTension = rope.Tensions[0];
            return result;
        }

        /// <summary>Static elongation (M + m_rope/2)·g·L/(E·A) in metres of the built rope under its load.</summary>
        private double StaticElongation(Rope rope)
        {
            RopeSettings s = rope.Settings;
            double load = 0.0;
            for (int l = 0; l < rope.LoadCount; l++) load += rope.GetParticleMass(rope.GetLoadParticle(l)) - s.LinearDensity * RestLength / (2.0 * SegmentCount);
            return (load + s.LinearDensity * RestLength / 2.0) * s.Gravity.Length * RestLength / s.AxialStiffness;
        }

        /// <summary>
        /// Largest distance in metres a recovered rope may reach from its anchor: the initial extent, or the
        /// rest length plus twice the static elongation (the overshoot of a released load), plus 10 %.
        /// </summary>
        public double ReachBound(StabilityResult result) => 1.1 * Math.Max(RestLength * Stretch, RestLength + 2.0 * result.StaticElongation);

        private static bool IsFinite(Rope rope)
        {
            for (int i = 0; i < rope.ParticleCount; i++)
                if (!float.IsFinite(rope.PositionX[i]) || !float.IsFinite(rope.PositionY[i]) || !float.IsFinite(rope.PositionZ[i]) || !rope.GetVelocity(i).IsFinite) return false;
            for (int j = 0; j < rope.SegmentCount; j++) if (!float.IsFinite(rope.Tensions[j])) return false;
            return true;
        }
    }

    /// <summary>What <see cref="StabilityCase.Run"/> measured.</summary>
    internal struct StabilityResult
    {
        /// <summary>True when positions, velocities, tensions and energy stayed finite throughout.</summary>
        public bool Finite;
        /// <summary>Total energy at the start in joules (elastic part: its upper bound within round-off).</summary>
        public double InitialEnergy;
        /// <summary>Initial energy, or the energy right after the teleport when larger (the work put in), in joules.</summary>
        public double EnergyCeiling;
        /// <summary>Largest excess of the total energy (elastic part: its lower bound within round-off) over <see cref="EnergyCeiling"/> in joules (0 = never gained).</summary>
        public double LargestEnergyGain;
        /// <summary>Substeps whose exact solve was violent (<see cref="StepReport.ViolentSubsteps"/>), summed over the run.</summary>
        public int ViolentSubsteps;
        /// <summary>Substeps that ended unconverged at their iteration limit (<see cref="StepReport.UnconvergedSubsteps"/>), summed over the run.</summary>
        public int UnconvergedSubsteps;
        /// <summary>Largest kinetic energy seen in joules.</summary>
        public double LargestKineticEnergy;
        /// <summary>Static elongation of the case under its load in metres.</summary>
        public double StaticElongation;
        /// <summary>Kinetic energy at the end in joules.</summary>
        public double FinalKineticEnergy;
        /// <summary>Largest particle distance from the anchor at the end in metres.</summary>
        public double FarthestFromAnchor;
        /// <summary>Tension of the top segment at the end in newtons.</summary>
        public double TopTension;
        /// <summary>Residual of the last step (strain).</summary>
        public double FinalResidual;
    }
}
