using System.Collections.Generic;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Scenarios
{
    /// <summary>One lab experiment as read from JSON (see Documentation~/lab.md). SI units throughout.</summary>
    public sealed class Scenario
    {
        /// <summary>Short identifier, used for output file names.</summary>
        public string Name = "scenario";
        /// <summary>Free text shown in the summary.</summary>
        public string Description = "";
        /// <summary>Gravity in m/s².</summary>
        public Float3 Gravity = new Float3(RopeParameters.Gravity.DefaultX, RopeParameters.Gravity.DefaultY, RopeParameters.Gravity.DefaultZ);
        /// <summary>Simulated time in s.</summary>
        public double Duration = 5.0;
        /// <summary>Host step (one Rope.Step call) in s.</summary>
        public double HostStep = 1.0 / 90.0;
        /// <summary>Solver configuration.</summary>
        public SolverSpec Solver = new SolverSpec();
        /// <summary>Rope material and discretisation.</summary>
        public RopeSpec Rope = new RopeSpec();
        /// <summary>Drag of the air (or fluid) on the rope, and the wind.</summary>
        public DragSpec Drag = new DragSpec();
        /// <summary>What holds particle 0.</summary>
        public AttachmentSpec Start = AttachmentSpec.FixedAt(Float3.Zero);
        /// <summary>What holds the last particle.</summary>
        public AttachmentSpec End = new AttachmentSpec { Kind = AttachmentKind.Free };
        /// <summary>Initial shape of the rope.</summary>
        public InitialSpec Initial = new InitialSpec();
        /// <summary>Static or kinematic colliders.</summary>
        public List<ColliderSpec> Colliders = new List<ColliderSpec>();
        /// <summary>Timed events (pin targets and velocities, releases, impulses, damping, cuts), sorted by time.</summary>
        public List<EventSpec> Events = new List<EventSpec>();
        /// <summary>Sampling and export settings.</summary>
        public OutputSpec Outputs = new OutputSpec();
        /// <summary>Which physics check the lab applies to the run (set by built-in scenarios).</summary>
        public ExpectationSpec Expect = new ExpectationSpec();

        /// <summary>
        /// True for a fall-arrest scenario (its check is "fall-arrest", or a body falls from <c>initial.fallHeight</c>):
        /// the only scenarios whose summary and plots carry the EN 355 / ANSI / OSHA limits.
        /// </summary>
        public bool IsFallArrest => Expect.Check == "fall-arrest" || (Initial.FallHeight.HasValue && End.Kind == AttachmentKind.Body);

        /// <summary>Number of host steps to cover <see cref="Duration"/>.</summary>
        public int StepCount => (int)System.Math.Ceiling(Duration / HostStep - 1e-9);
    }

    /// <summary>Constraint solver choice.</summary>
    public enum SolverMethod
    {
        /// <summary>XPBD Gauss–Seidel projections.</summary>
        GaussSeidel,
        /// <summary>Exact tridiagonal solve of the whole chain per iteration.</summary>
        ExactChain,
    }

    /// <summary>solver {…} block. Defaults are the parameter table's (<see cref="RopeParameters"/>).</summary>
    public sealed class SolverSpec
    {
        /// <summary>Constraint solver.</summary>
        public SolverMethod Method = RopeParameters.Solver.Default == HookeRope.Solver.ConstraintSolverKind.GaussSeidel ? SolverMethod.GaussSeidel : SolverMethod.ExactChain;
        /// <summary>Substeps per host step.</summary>
        public int Substeps = RopeParameters.Substeps.Default;
        /// <summary>Iterations per substep.</summary>
        public int Iterations = RopeParameters.Iterations.Default;
        /// <summary>XPBD constraint damping β in s.</summary>
        public double Damping = RopeParameters.Damping.Default;
        /// <summary>True: rope (pulls only); false: rod (bilateral).</summary>
        public bool TensionOnly = RopeParameters.TensionModel.Default == HookeRope.Solver.TensionModel.TensionOnly;
        /// <summary>Time integrator of each substep (backward Euler or BDF2).</summary>
        public HookeRope.Solver.TimeIntegrator Integrator = RopeParameters.Integrator.Default;

        /// <summary>JSON name of an integrator: "backward-euler" or "bdf2".</summary>
        public static string IntegratorJson(HookeRope.Solver.TimeIntegrator integrator) =>
            integrator == HookeRope.Solver.TimeIntegrator.Bdf2 ? "bdf2" : "backward-euler";
    }

    /// <summary>rope {…} block. Defaults are the parameter table's (<see cref="RopeParameters"/>).</summary>
    public sealed class RopeSpec
    {
        /// <summary>Young's modulus in Pa used when neither youngsModulus nor axialStiffness is given.</summary>
        public const double DefaultYoungsModulus = RopeParameters.YoungsModulus.Default;
        /// <summary>Density in kg/m³ used when neither density nor linearDensity is given.</summary>
        public const double DefaultDensity = RopeParameters.Density.Default;

        /// <summary>Rest length in m.</summary>
        public double RestLength = RopeParameters.RestLength.Default;
        /// <summary>Number of segments.</summary>
        public int Segments = RopeParameters.SegmentCount.Default;
        /// <summary>Rest radius R in m.</summary>
        public double Radius = RopeParameters.Radius.Default;
        /// <summary>Young's modulus in Pa (null when axialStiffness is given).</summary>
        public double? YoungsModulus;
        /// <summary>Axial stiffness E·A in N (null when youngsModulus is given).</summary>
        public double? AxialStiffness;
        /// <summary>Linear density in kg/m (null when density is given).</summary>
        public double? LinearDensity;
        /// <summary>Density in kg/m³ (null when linearDensity is given).</summary>
        public double? Density;
        /// <summary>Thin the rope with its strain through the Poisson ratio.</summary>
        public bool PoissonThinning = RopeParameters.PoissonThinning.Default;
        /// <summary>Poisson ratio ν in [−1, 0.5].</summary>
        public double PoissonRatio = RopeParameters.PoissonRatio.Default;
        /// <summary>Let a neck form at the defect.</summary>
        public bool Necking = RopeParameters.Necking.Default;
        /// <summary>Neck model: "zone" (a short neck zone at the defect) or "paper" (one hyperbola over the rope).</summary>
        public string NeckMode = RopeParameters.NeckMode.Default == HookeRope.Radius.NeckMode.Paper ? "paper" : "zone";
        /// <summary>Neck onset radius r_min as a fraction of R.</summary>
        public double NeckRadiusFraction = RopeParameters.NeckRadiusFraction.Default;
        /// <summary>Weak spot where the neck starts and the rope breaks, as a fraction of the rest length from the start, 0…1.</summary>
        public double DefectPosition = RopeParameters.DefectPosition.Default;
        /// <summary>Zone neck: rest length of the neck zone in rope diameters 2R.</summary>
        public double NeckZoneDiameters = RopeParameters.NeckZoneDiameters.Default;
        /// <summary>Zone neck: strain beyond onset over which the neck deepens to the full hyperbola.</summary>
        public double NeckGrowthStrain = RopeParameters.NeckGrowthStrain.Default;
        /// <summary>A segment shorter than its rest length keeps the rest radius.</summary>
        public bool SlackKeepsRestRadius = RopeParameters.SlackKeepsRestRadius.Default;
        /// <summary>Let the rope break at the defect.</summary>
        public bool Fracture = RopeParameters.Fracture.Default;
        /// <summary>Strain l/L − 1 of the defect segment at which it breaks.</summary>
        public double BreakStrain = RopeParameters.BreakStrain.Default;
        /// <summary>Neck radius (fraction of R) at which the defect breaks when necking is on.</summary>
        public double BreakRadiusFraction = RopeParameters.BreakRadiusFraction.Default;
        /// <summary>Vertices around the tube mesh.</summary>
        public int RadialSegments = RopeParameters.RadialSegments.Default;
        /// <summary>How far the adaptive rings let the surface leave the smooth tube along the rope, × the polygon's depth R·(1 − cos π/N).</summary>
        public double RingTolerance = RopeParameters.RingTolerance.Default;
        /// <summary>Seed of the random parts (burr strands of broken ends).</summary>
        public int Seed = RopeParameters.BurrSeed.Default;
        /// <summary>Material law (issue 15): "elastic" or "elastic-plastic".</summary>
        public string MaterialModel = RopeParameters.MaterialModel.Default == HookeRope.Solver.MaterialModel.ElasticPlastic ? "elastic-plastic" : "elastic";
        /// <summary>Elastic–plastic: yield strain ε_y (the yield force is E·A·ε_y).</summary>
        public double YieldStrain = RopeParameters.YieldStrain.Default;
        /// <summary>Elastic–plastic: hardening modulus H in N (0 = a plateau).</summary>
        public double HardeningModulus = RopeParameters.HardeningModulus.Default;
        /// <summary>Elastic–plastic: strain at which the neck forms at the defect.</summary>
        public double NeckingStrain = RopeParameters.NeckingStrain.Default;
        /// <summary>Elastic–plastic: strain of the neck at which its force is zero and the rope breaks.</summary>
        public double UltimateStrain = RopeParameters.UltimateStrain.Default;
        /// <summary>An energy absorber in series with the last segment (the end).</summary>
        public bool EnergyAbsorber = RopeParameters.EnergyAbsorber.Default;
        /// <summary>Energy absorber: plateau force F_p in N.</summary>
        public double AbsorberForce = RopeParameters.AbsorberForce.Default;
        /// <summary>Energy absorber: largest deployment in m.</summary>
        public double AbsorberDeployment = RopeParameters.AbsorberDeployment.Default;

        /// <summary>True with the elastic–plastic material.</summary>
        public bool IsPlastic => MaterialModel == "elastic-plastic";

        /// <summary>Cross-section area πR² in m².</summary>
        public double Area => System.Math.PI * Radius * Radius;
        /// <summary>E·A in N, from whichever of the two was given.</summary>
        public double ResolvedAxialStiffness => AxialStiffness ?? (YoungsModulus ?? DefaultYoungsModulus) * Area;
        /// <summary>μ in kg/m, from whichever of the two was given.</summary>
        public double ResolvedLinearDensity => LinearDensity ?? (Density ?? DefaultDensity) * Area;
        /// <summary>Total rope mass in kg.</summary>
        public double Mass => ResolvedLinearDensity * RestLength;
    }

    /// <summary>drag {…} block. Defaults are the parameter table's (<see cref="RopeParameters"/>): no drag, air at 1.2 kg/m³, no wind.</summary>
    public sealed class DragSpec
    {
        /// <summary>Viscous drag c per metre of rope in N·s/m².</summary>
        public double ViscousDrag = RopeParameters.ViscousDrag.Default;
        /// <summary>Drag coefficient C_d across the rope.</summary>
        public double DragCoefficient = RopeParameters.DragCoefficient.Default;
        /// <summary>Skin-friction coefficient C_f along the rope.</summary>
        public double SkinFriction = RopeParameters.SkinFriction.Default;
        /// <summary>Air (fluid) density in kg/m³.</summary>
        public double AirDensity = RopeParameters.AirDensity.Default;
        /// <summary>Air velocity in m/s.</summary>
        public Float3 Wind = new Float3(RopeParameters.Wind.DefaultX, RopeParameters.Wind.DefaultY, RopeParameters.Wind.DefaultZ);

        /// <summary>True when some drag acts (as <see cref="HookeRope.Solver.RopeSettings.HasDrag"/>).</summary>
        public bool Acts => ViscousDrag > 0 || (AirDensity > 0 && (DragCoefficient > 0 || SkinFriction > 0));

        /// <summary>True when a wind blows through drag that acts: the air then does work on the rope.</summary>
        public bool Blows => Acts && (Wind.X != 0 || Wind.Y != 0 || Wind.Z != 0);
    }

    /// <summary>How an end of the rope is held.</summary>
    public enum AttachmentKind
    {
        /// <summary>Nothing holds it.</summary>
        Free,
        /// <summary>Pinned at a point.</summary>
        Fixed,
        /// <summary>Pinned to a point moving through keyframes.</summary>
        Keyframes,
        /// <summary>A point mass (worker, weight) attached to the end particle.</summary>
        Body,
    }

    /// <summary>One keyframe of a moving anchor.</summary>
    public struct Keyframe
    {
        /// <summary>Time in s.</summary>
        public double Time;
        /// <summary>Position in m.</summary>
        public Float3 Position;
    }

    /// <summary>start/end {…}.</summary>
    public sealed class AttachmentSpec
    {
        /// <summary>Kind of attachment.</summary>
        public AttachmentKind Kind = AttachmentKind.Fixed;
        /// <summary>Position in m (fixed, body; null = derived from the other end).</summary>
        public Float3? Position;
        /// <summary>Keyframes (moving anchors), sorted by time.</summary>
        public List<Keyframe> Keys = new List<Keyframe>();
        /// <summary>Body mass in kg.</summary>
        public double Mass;
        /// <summary>Body initial velocity in m/s.</summary>
        public Float3 Velocity;
        /// <summary>Pin compliance in m/N (0 = rigid).</summary>
        public double Compliance = RopeParameters.AttachmentCompliance.Default;

        /// <summary>Mass hanging on this end in kg: <see cref="Mass"/> for a body, 0 otherwise.</summary>
        public double LoadMass => Kind == AttachmentKind.Body ? Mass : 0;

        /// <summary>A fixed anchor.</summary>
        public static AttachmentSpec FixedAt(Float3 p) => new AttachmentSpec { Kind = AttachmentKind.Fixed, Position = p };

        /// <summary>Anchor position at time t (keyframes interpolated linearly, held outside).</summary>
        public Float3 PositionAt(double t)
        {
            if (Kind != AttachmentKind.Keyframes) return Position ?? Float3.Zero;
            if (t <= Keys[0].Time) return Keys[0].Position;
            for (int i = 1; i < Keys.Count; i++)
            {
                if (t <= Keys[i].Time)
                {
                    double span = Keys[i].Time - Keys[i - 1].Time;
                    float f = span <= 0 ? 1f : (float)((t - Keys[i - 1].Time) / span);
                    return Float3.Lerp(Keys[i - 1].Position, Keys[i].Position, f);
                }
            }
            return Keys[Keys.Count - 1].Position;
        }
    }

    /// <summary>Initial shape.</summary>
    public enum InitialShape
    {
        /// <summary>Straight from start to end, stretched by <see cref="InitialSpec.Stretch"/>.</summary>
        Straight,
        /// <summary>Unstretched, folded into a V when the ends are closer than the rest length.</summary>
        Slack,
        /// <summary>The inextensible catenary through both ends (same height).</summary>
        Catenary,
    }

    /// <summary>initial {…}.</summary>
    public sealed class InitialSpec
    {
        /// <summary>Shape.</summary>
        public InitialShape Shape = InitialShape.Straight;
        /// <summary>Initial strain for a straight rope whose end is not given (end = start + down·L(1+stretch)).</summary>
        public double Stretch;
        /// <summary>Free-fall height in m before the rope goes taut (raises the end body), or null.</summary>
        public double? FallHeight;
    }

    /// <summary>Collider kind.</summary>
    public enum ColliderKind
    {
        /// <summary>Half-space.</summary>
        Plane,
        /// <summary>Sphere.</summary>
        Sphere,
        /// <summary>Capsule between two points.</summary>
        Capsule,
        /// <summary>Oriented box.</summary>
        Box,
    }

    /// <summary>colliders[i] {…}.</summary>
    public sealed class ColliderSpec
    {
        /// <summary>Kind.</summary>
        public ColliderKind Kind;
        /// <summary>Centre (sphere, box), a point on the plane, or capsule end A, in m.</summary>
        public Float3 Center;
        /// <summary>Plane normal (unit after parsing).</summary>
        public Float3 Normal = new Float3(0f, 1f, 0f);
        /// <summary>Capsule end B in m.</summary>
        public Float3 PointB;
        /// <summary>Radius in m (sphere, capsule).</summary>
        public double Radius = 0.1;
        /// <summary>Box half extents in m.</summary>
        public Float3 HalfExtents = new Float3(0.5f, 0.5f, 0.5f);
        /// <summary>Box rotation as Euler angles in degrees (applied Z, X, Y like Unity).</summary>
        public Float3 EulerDegrees;
        /// <summary>Coulomb friction coefficient.</summary>
        public double Friction = RopeParameters.Friction.Default;
    }

    /// <summary>outputs {…}.</summary>
    public sealed class OutputSpec
    {
        /// <summary>CSV rows per simulated second (0 = every host step).</summary>
        public double SampleRate = 200.0;
        /// <summary>Instants (s) of the radius profiles (plot and NAME-radius.csv).</summary>
        public List<double> ProfileTimes = new List<double>();
        /// <summary>Instants (s) at which the tube mesh is exported to glTF (empty = none).</summary>
        public List<double> GltfTimes = new List<double>();
    }

    /// <summary>What the built-in scenario checks (read by tests and the summary). Optional in user files.</summary>
    public sealed class ExpectationSpec
    {
        /// <summary>Analytic check: "none", "fall-arrest", "static-hang", "period", "catenary", "poisson", "neck", "fracture", "collision", "amplitude", "rebound", "snatch", "absorber", "plastic", "settle".</summary>
        public string Check = "none";
    }
}
