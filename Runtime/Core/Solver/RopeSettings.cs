using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// Validated, mutable rope parameters in SI units. Every setter throws an
    /// <see cref="ArgumentException"/> naming the property and its valid range. A live
    /// <see cref="Rope"/> picks up changes at its next step (or at <see cref="Rope.ApplySettings"/>),
    /// except <see cref="SegmentCount"/>, which is read only when a rope is built.
    /// Cross-section A = π·R²: <see cref="YoungsModulus"/>/<see cref="AxialStiffness"/> and
    /// <see cref="Density"/>/<see cref="LinearDensity"/> are two views of one value each; setting
    /// <see cref="Radius"/> keeps the material (E, ρ) and rescales E·A and the linear density.
    /// </summary>
    public sealed class RopeSettings
    {
        // defaults: the parameter table's (the component and prefab values)
        private float restLength = RopeParameters.RestLength.Default;
        private int segmentCount = RopeParameters.SegmentCount.Default;
        private float radius = RopeParameters.Radius.Default;
        private float youngsModulus = RopeParameters.YoungsModulus.Default;
        private float density = RopeParameters.Density.Default;
        private float damping = RopeParameters.Damping.Default;
        private Float3 gravity = new Float3(RopeParameters.Gravity.DefaultX, RopeParameters.Gravity.DefaultY, RopeParameters.Gravity.DefaultZ);
        private int substeps = RopeParameters.Substeps.Default;
        private int iterations = RopeParameters.Iterations.Default;
        private ConstraintSolverKind solver = RopeParameters.Solver.Default;
        private TensionModel tension = RopeParameters.TensionModel.Default;
        private TimeIntegrator integrator = DefaultIntegrator;
        private GaussSeidelKernel gaussSeidelKernel = RopeParameters.GaussSeidelKernel.Default;
        private float viscousDrag = RopeParameters.ViscousDrag.Default;
        private float dragCoefficient = RopeParameters.DragCoefficient.Default;
        private float skinFriction = RopeParameters.SkinFriction.Default;
        private float airDensity = RopeParameters.AirDensity.Default;
        private Float3 wind = new Float3(RopeParameters.Wind.DefaultX, RopeParameters.Wind.DefaultY, RopeParameters.Wind.DefaultZ);

        /// <summary>Default of <see cref="Integrator"/>.</summary>
        public const TimeIntegrator DefaultIntegrator = TimeIntegrator.Bdf2;

        /// <summary>Incremented by every successful setter; a rope re-reads its settings when it changes.</summary>
        public int Version { get; private set; }

        /// <summary>Unstretched length of the whole rope in metres, in [0.01, 10000] (<see cref="RopeParameters.RestLength"/>). Default 2 m.</summary>
        public float RestLength { get => restLength; set => Set(ref restLength, value, RopeParameters.RestLength.Row); }

        /// <summary>Number of segments (particles = segments + 1), in [1, 10000]. Default 24. Read when a rope is built.</summary>
        public int SegmentCount { get => segmentCount; set => Set(ref segmentCount, value, RopeParameters.SegmentCount.Row); }

        /// <summary>Rest radius R of the rope in metres, in (0, 1] (<see cref="RopeParameters.Radius"/>). Default 0.008 m. Keeps E and ρ; rescales E·A and linear density.</summary>
        public float Radius { get => radius; set => Set(ref radius, value, RopeParameters.Radius.Row); }

        /// <summary>Cross-section area π·R² in square metres.</summary>
        public float Area => MathF.PI * radius * radius;

        /// <summary>Young's modulus E in pascals, in (0, 1e13] or +inf = inextensible (<see cref="RopeParameters.YoungsModulus"/>). Default 1.5e8 Pa.</summary>
        public float YoungsModulus { get => youngsModulus; set => Set(ref youngsModulus, value, RopeParameters.YoungsModulus.Row); }

        /// <summary>Axial stiffness E·A in newtons, in (0, 1e12] or +inf (<see cref="RopeParameters.AxialStiffness"/>); setting it sets E = (E·A)/(π·R²).</summary>
        public float AxialStiffness { get => youngsModulus * Area; set => SetPerArea(ref youngsModulus, value, RopeParameters.AxialStiffness.Row); }

        /// <summary>Material density ρ in kg/m³, in (0, 1e5] (<see cref="RopeParameters.Density"/>). Default 1140 kg/m³. Sets the linear density ρ·π·R².</summary>
        public float Density { get => density; set => Set(ref density, value, RopeParameters.Density.Row); }

        /// <summary>Mass per unit rest length μ in kg/m, in (0, 1e4] (<see cref="RopeParameters.LinearDensity"/>); setting it sets ρ = μ/(π·R²).</summary>
        public float LinearDensity { get => density * Area; set => SetPerArea(ref density, value, RopeParameters.LinearDensity.Row); }

        /// <summary>
        /// XPBD constraint damping β in seconds, in [0, 10] (Macklin 2016, eq. 26): a dashpot of
        /// β·k in parallel with each segment of stiffness k. Removes vibration energy without moving
        /// the static solution. Default 0.002 s.
        /// </summary>
        public float Damping { get => damping; set => Set(ref damping, value, RopeParameters.Damping.Row); }

        /// <summary>Gravity acceleration in m/s², each component in [−1000, 1000]. Default (0, −9.81, 0).</summary>
        public Float3 Gravity
        {
            get => gravity;
            set
            {
                ParameterInfo row = RopeParameters.Gravity.Row;
                RopeParameters.Check(value.X, row); RopeParameters.Check(value.Y, row); RopeParameters.Check(value.Z, row);
                gravity = value;
                Version++;
            }
        }

        /// <summary>Substeps per host step, in [1, 1000]. Default 8.</summary>
        public int Substeps { get => substeps; set => Set(ref substeps, value, RopeParameters.Substeps.Row); }

        /// <summary>Constraint iterations per substep, in [1, 1000]. Default 1.</summary>
        public int Iterations { get => iterations; set => Set(ref iterations, value, RopeParameters.Iterations.Row); }

        /// <summary>Constraint solver. Default <see cref="ConstraintSolverKind.ExactChain"/>.</summary>
        public ConstraintSolverKind Solver
        {
            get => solver;
            set { CheckChoice((int)value, (int)ConstraintSolverKind.GaussSeidel, (int)ConstraintSolverKind.ExactChain, nameof(Solver)); solver = value; Version++; }
        }

        /// <summary>Rope (tension only) or rod (bilateral). Default <see cref="TensionModel.TensionOnly"/>.</summary>
        public TensionModel Tension
        {
            get => tension;
            set { CheckChoice((int)value, (int)TensionModel.TensionOnly, (int)TensionModel.Bilateral, nameof(Tension)); tension = value; Version++; }
        }

        /// <summary>
        /// Time integrator of each substep: <see cref="TimeIntegrator.Bdf2"/> (second order, low dissipation) or
        /// <see cref="TimeIntegrator.BackwardEuler"/> (most robust, dissipative). An unknown value throws an
        /// <see cref="ArgumentException"/> naming the property and changes nothing.
        /// </summary>
        public TimeIntegrator Integrator
        {
            get => integrator;
            set { CheckChoice((int)value, (int)TimeIntegrator.BackwardEuler, (int)TimeIntegrator.Bdf2, nameof(Integrator)); integrator = value; Version++; }
        }

        /// <summary>
        /// The Gauss–Seidel kernel (<see cref="RopeParameters.GaussSeidelKernel"/>; read only when <see cref="Solver"/> is
        /// <see cref="ConstraintSolverKind.GaussSeidel"/>): <see cref="Solver.GaussSeidelKernel.Precise"/> (default, every
        /// result as before) or the opt-in <see cref="Solver.GaussSeidelKernel.FusedSingle"/>, one single-precision pass
        /// per substep, which runs only for a rope with <see cref="Integrator"/> = <see cref="TimeIntegrator.BackwardEuler"/>,
        /// no colliders, no drag (<see cref="HasDrag"/> false), no compliant pins and the elastic material without an
        /// energy absorber; any other rope runs the precise kernel. An unknown value throws an
        /// <see cref="ArgumentException"/> naming the property and changes nothing.
        /// </summary>
        public GaussSeidelKernel GaussSeidelKernel
        {
            get => gaussSeidelKernel;
            set { CheckChoice((int)value, (int)GaussSeidelKernel.Precise, (int)GaussSeidelKernel.FusedSingle, nameof(GaussSeidelKernel)); gaussSeidelKernel = value; Version++; }
        }

        /// <summary>
        /// Viscous drag coefficient c in N·s/m², in [0, 1e4] (<see cref="RopeParameters.ViscousDrag"/>): a force −c·(v − <see cref="Wind"/>)
        /// per metre of rope, applied implicitly (it never adds energy). A uniform rope's swing decays as exp(−c·t/(2μ)) and it
        /// falls at most at μ·g/c (μ = <see cref="LinearDensity"/>). Default 0 (off).
        /// </summary>
        public float ViscousDrag { get => viscousDrag; set => Set(ref viscousDrag, value, RopeParameters.ViscousDrag.Row); }

        /// <summary>
        /// Drag coefficient C_d (dimensionless), in [0, 10] (<see cref="RopeParameters.DragCoefficient"/>) of the quadratic air drag
        /// across the rope: ½·ρ·C_d·2R·|v⊥|·v⊥ per metre, v⊥ the velocity across the rope relative to the air (ρ =
        /// <see cref="AirDensity"/>, R = <see cref="Radius"/>). About 1.0–1.2 for a rope in air. Default 0 (off).
        /// </summary>
        public float DragCoefficient { get => dragCoefficient; set => Set(ref dragCoefficient, value, RopeParameters.DragCoefficient.Row); }

        /// <summary>
        /// Skin-friction coefficient C_f (dimensionless), in [0, 1] (<see cref="RopeParameters.SkinFriction"/>) of the axial air drag
        /// along the rope: ½·ρ·C_f·2πR·|v∥|·v∥ per metre, v∥ the velocity along the rope relative to the air. About 0.01. Default 0 (off).
        /// </summary>
        public float SkinFriction { get => skinFriction; set => Set(ref skinFriction, value, RopeParameters.SkinFriction.Row); }

        /// <summary>Density ρ of the air (or fluid) in kg/m³, in [0, 1e4] (<see cref="RopeParameters.AirDensity"/>). Scales C_d and C_f. Default 1.2 kg/m³.</summary>
        public float AirDensity { get => airDensity; set => Set(ref airDensity, value, RopeParameters.AirDensity.Row); }

        /// <summary>
        /// Velocity of the air in m/s (world axes; the rope-local frame is the world frame shifted, so a velocity is the same in
        /// both), each component in [−1000, 1000] (<see cref="RopeParameters.Wind"/>); a non-finite component throws. The drag acts
        /// on the rope's velocity relative to it; without drag it has no effect. Default (0, 0, 0).
        /// </summary>
        public Float3 Wind
        {
            get => wind;
            set
            {
                ParameterInfo row = RopeParameters.Wind.Row;
                RopeParameters.Check(value.X, row); RopeParameters.Check(value.Y, row); RopeParameters.Check(value.Z, row);
                wind = value;
                Version++;
            }
        }

        /// <summary>True when some drag acts (c &gt; 0, or ρ &gt; 0 with C_d or C_f &gt; 0). False costs nothing per step.</summary>
        public bool HasDrag => viscousDrag > 0f || (airDensity > 0f && (dragCoefficient > 0f || skinFriction > 0f));

        /// <summary>A copy with the same values (version 0).</summary>
        public RopeSettings Clone()
        {
            var copy = (RopeSettings)MemberwiseClone();
            copy.Version = 0;
            return copy;
        }

        private void Set(ref float field, float value, ParameterInfo row)
        {
            field = RopeParameters.Check(value, row);
            Version++;
        }

        private void Set(ref int field, int value, ParameterInfo row)
        {
            field = RopeParameters.Check(value, row);
            Version++;
        }

        /// <summary>
        /// Sets a material value from its per-length view (E·A → E, μ → ρ): <paramref name="value"/>/(π·R²) after the row's
        /// check; throws naming the row when the radius makes the quotient 0 or overflow a finite value.
        /// </summary>
        private void SetPerArea(ref float field, float value, ParameterInfo row)
        {
            RopeParameters.Check(value, row);
            float perArea = value / Area;
            if (!(perArea > 0f) || (float.IsPositiveInfinity(perArea) && float.IsFinite(value)))
                throw new ArgumentOutOfRangeException(row.Name, value, row.Name + " must be in " + row.RangeText + " (out of range for the radius " + radius + " m).");
            field = perArea;
            Version++;
        }

        private static void CheckChoice(int value, int first, int second, string name)
        {
            if (value != first && value != second)
                throw new ArgumentOutOfRangeException(name, value, name + " must be one of its named values (" + first + " or " + second + ")");
        }

        // ---- Material law (issue 15): plasticity, necking, energy absorber ----------------------------------------------

        private MaterialModel materialModel = RopeParameters.MaterialModel.Default;
        private float yieldStrain = RopeParameters.YieldStrain.Default;
        private float hardeningModulus = RopeParameters.HardeningModulus.Default;
        private float neckingStrain = RopeParameters.NeckingStrain.Default;
        private float ultimateStrain = RopeParameters.UltimateStrain.Default;
        private bool energyAbsorber = RopeParameters.EnergyAbsorber.Default;
        private float absorberForce = RopeParameters.AbsorberForce.Default;
        private float absorberDeployment = RopeParameters.AbsorberDeployment.Default;

        /// <summary>
        /// The segments' constitutive law (<see cref="RopeParameters.MaterialModel"/>): <see cref="Solver.MaterialModel.Elastic"/>
        /// (default) or <see cref="Solver.MaterialModel.ElasticPlastic"/>. Switching to elastic–plastic checks
        /// <see cref="YieldStrain"/> ≤ <see cref="NeckingStrain"/> &lt; <see cref="UltimateStrain"/> and throws an
        /// <see cref="ArgumentException"/> naming the first value out of order; switching back to elastic forgets the
        /// permanent set.
        /// </summary>
        public MaterialModel MaterialModel
        {
            get => materialModel;
            set
            {
                CheckChoice((int)value, (int)MaterialModel.Elastic, (int)MaterialModel.ElasticPlastic, nameof(MaterialModel));
                if (value == MaterialModel.ElasticPlastic) CheckPlasticOrder(yieldStrain, neckingStrain, ultimateStrain);
                materialModel = value;
                Version++;
            }
        }

        /// <summary>
        /// Elastic–plastic: elastic strain at yield ε_y (dimensionless), in (0, 1000] (<see cref="RopeParameters.YieldStrain"/>)
        /// and, with the plastic material, at most <see cref="NeckingStrain"/> and below <see cref="UltimateStrain"/>. The yield
        /// force is E·A·ε_y (<see cref="YieldForce"/>). Default 0.1.
        /// </summary>
        public float YieldStrain
        {
            get => yieldStrain;
            set => SetPlastic(ref yieldStrain, value, RopeParameters.YieldStrain.Row, value, neckingStrain, ultimateStrain);
        }

        /// <summary>Yield force E·A·ε_y in newtons (+∞ for an inextensible rope, which never yields).</summary>
        public float YieldForce => AxialStiffness * yieldStrain;

        /// <summary>
        /// Elastic–plastic: hardening modulus H in newtons, in [0, 1e12] (<see cref="RopeParameters.HardeningModulus"/>): the
        /// force grows by H per unit plastic strain after yield; 0 = a plateau. Negative values throw (softening is the
        /// neck's). Default 5000 N.
        /// </summary>
        public float HardeningModulus { get => hardeningModulus; set => Set(ref hardeningModulus, value, RopeParameters.HardeningModulus.Row); }

        /// <summary>
        /// Elastic–plastic: strain on the hardening curve at which the neck forms at the defect segment (dimensionless), in
        /// (0, 1000] (<see cref="RopeParameters.NeckingStrain"/>) and, with the plastic material, in
        /// [<see cref="YieldStrain"/>, <see cref="UltimateStrain"/>). The rope's force peaks there. Default 0.45.
        /// </summary>
        public float NeckingStrain
        {
            get => neckingStrain;
            set => SetPlastic(ref neckingStrain, value, RopeParameters.NeckingStrain.Row, yieldStrain, value, ultimateStrain);
        }

        /// <summary>
        /// Elastic–plastic: strain of the neck segment at which its force has fallen to zero and the rope breaks (elongation at
        /// break, dimensionless), in (0, 1000] (<see cref="RopeParameters.UltimateStrain"/>) and, with the plastic material,
        /// above <see cref="NeckingStrain"/>. Default 0.6.
        /// </summary>
        public float UltimateStrain
        {
            get => ultimateStrain;
            set => SetPlastic(ref ultimateStrain, value, RopeParameters.UltimateStrain.Row, yieldStrain, neckingStrain, value);
        }

        /// <summary>
        /// Sets the whole plastic law at once (strains dimensionless, <paramref name="hardening"/> in N), checking each against
        /// its table range and their order ε_y ≤ ε_n &lt; ε_u, and switches <see cref="MaterialModel"/> to elastic–plastic.
        /// Nothing changes when a value is rejected.
        /// </summary>
        public void SetPlasticity(float yield, float hardening, float necking, float ultimate)
        {
            RopeParameters.Check(yield, RopeParameters.YieldStrain.Row);
            RopeParameters.Check(hardening, RopeParameters.HardeningModulus.Row);
            RopeParameters.Check(necking, RopeParameters.NeckingStrain.Row);
            RopeParameters.Check(ultimate, RopeParameters.UltimateStrain.Row);
            CheckPlasticOrder(yield, necking, ultimate);
            yieldStrain = yield;
            hardeningModulus = hardening;
            neckingStrain = necking;
            ultimateStrain = ultimate;
            materialModel = MaterialModel.ElasticPlastic;
            Version++;
        }

        /// <summary>An energy absorber in series with the last segment (<see cref="RopeParameters.EnergyAbsorber"/>). Default false.</summary>
        public bool EnergyAbsorber
        {
            get => energyAbsorber;
            set { energyAbsorber = value; Version++; }
        }

        /// <summary>Plateau force F_p of the energy absorber in newtons, in (0, 1e7] (<see cref="RopeParameters.AbsorberForce"/>); ≤ 0 throws. Default 4000 N.</summary>
        public float AbsorberForce { get => absorberForce; set => Set(ref absorberForce, value, RopeParameters.AbsorberForce.Row); }

        /// <summary>Largest deployment of the energy absorber in metres, in (0, 100] (<see cref="RopeParameters.AbsorberDeployment"/>). Default 1.75 m.</summary>
        public float AbsorberDeployment { get => absorberDeployment; set => Set(ref absorberDeployment, value, RopeParameters.AbsorberDeployment.Row); }

        /// <summary>
        /// The energy-absorber preset: turns the absorber on with the plateau force <paramref name="plateauForce"/> (N, in
        /// (0, 1e7]) and the deployment length <paramref name="deploymentLength"/> (m, in (0, 100]); defaults are a typical
        /// EN 355 absorber (4 kN, 1.75 m). Nothing changes when a value is rejected.
        /// </summary>
        public void UseEnergyAbsorber(float plateauForce = RopeParameters.AbsorberForce.Default, float deploymentLength = RopeParameters.AbsorberDeployment.Default)
        {
            RopeParameters.Check(plateauForce, RopeParameters.AbsorberForce.Row);
            RopeParameters.Check(deploymentLength, RopeParameters.AbsorberDeployment.Row);
            absorberForce = plateauForce;
            absorberDeployment = deploymentLength;
            energyAbsorber = true;
            Version++;
        }

        /// <summary>True when the segments need the plastic state: the elastic–plastic material or an energy absorber.</summary>
        internal bool HasPlasticity => materialModel == MaterialModel.ElasticPlastic || energyAbsorber;

        /// <summary>A strain of the plastic law: the table check, then (plastic material only) the order ε_y ≤ ε_n &lt; ε_u with the new value.</summary>
        private void SetPlastic(ref float field, float value, ParameterInfo row, float yield, float necking, float ultimate)
        {
            RopeParameters.Check(value, row);
            if (materialModel == MaterialModel.ElasticPlastic) CheckPlasticOrder(yield, necking, ultimate, row.Name);
            field = value;
            Version++;
        }

        /// <summary>
        /// Throws an <see cref="ArgumentOutOfRangeException"/> when ε_y ≤ ε_n &lt; ε_u does not hold, naming
        /// <paramref name="setting"/> (the parameter being set; null: the first one out of order) and its valid range given the others.
        /// </summary>
        private static void CheckPlasticOrder(float yield, float necking, float ultimate, string setting = null)
        {
            bool yieldOk = yield <= necking && yield < ultimate, neckOk = necking >= yield && necking < ultimate, ultimateOk = ultimate > necking && ultimate > yield;
            if (yieldOk && neckOk && ultimateOk) return;
            string name = setting ?? (!yieldOk ? nameof(YieldStrain) : !neckOk ? nameof(NeckingStrain) : nameof(UltimateStrain));
            if (name == nameof(YieldStrain))
                throw new ArgumentOutOfRangeException(name, yield, "YieldStrain must be in (0, NeckingStrain = " + Text(necking)
                    + "] and below UltimateStrain = " + Text(ultimate) + " (the rope yields before it necks, and before the ultimate (break) strain).");
            if (name == nameof(NeckingStrain))
                throw new ArgumentOutOfRangeException(name, necking, "NeckingStrain must be in [YieldStrain = " + Text(yield)
                    + ", UltimateStrain = " + Text(ultimate) + ") (the neck forms on the plastic branch, before the break).");
            throw new ArgumentOutOfRangeException(name, ultimate, "UltimateStrain must be in (max(YieldStrain, NeckingStrain) = " + Text(Math.Max(yield, necking))
                + ", 1000] (the neck softens from the necking strain to zero force at the ultimate (break) strain).");
        }

        private static string Text(float value) => value.ToString(System.Globalization.CultureInfo.InvariantCulture);
    }
}
