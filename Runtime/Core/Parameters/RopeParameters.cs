using System;
using System.Collections.Generic;
using System.Globalization;
using ConstraintSolverKind = HookeRope.Solver.ConstraintSolverKind;
using NeckModeKind = HookeRope.Radius.NeckMode;
using TensionModelKind = HookeRope.Solver.TensionModel;
using TimeIntegratorKind = HookeRope.Solver.TimeIntegrator;
using GaussSeidelKernelKind = HookeRope.Solver.GaussSeidelKernel;
using MaterialModelKind = HookeRope.Solver.MaterialModel;

namespace HookeRope
{
    /// <summary>
    /// The one table of user-facing rope parameters: for each, its name, label, SI unit, valid range, default (the
    /// component and prefab value), tooltip and lab JSON name. Each parameter is a nested static class of consts, so
    /// Unity attributes can use them (<c>[Range(RopeParameters.Radius.Min, RopeParameters.Radius.Max)]</c>), and a
    /// <see cref="ParameterInfo"/> row in <see cref="All"/>. The component, the core settings and the lab parser
    /// read their ranges and defaults from here; <see cref="Check(float, ParameterInfo)"/> is the setter check and
    /// <see cref="Clamp(ref float, ParameterInfo)"/> the inspector clamp.
    /// </summary>
    public static class RopeParameters
    {
        // ---- Material ---------------------------------------------------------------------------------------

        /// <summary>Whether the stiffness is edited as Young's modulus E or as axial stiffness E·A (0 = E, 1 = E·A).</summary>
        public static class StiffnessInput
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(StiffnessInput);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Stiffness input";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (none: the lab takes youngsModulus or axialStiffness).</summary>
            public const string Json = null;
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Edit the stiffness as Young's modulus E (Pa) or as axial stiffness E·A (N); the other follows from A = πR².";
            /// <summary>Default: 0 = Young's modulus.</summary>
            public const int Default = 0;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Enum, 0, 1, Default, Tooltip, Json, true);
        }

        /// <summary>Young's modulus E in pascals; +∞ = inextensible (core only).</summary>
        public static class YoungsModulus
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(YoungsModulus);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Young's modulus";
            /// <summary>Unit.</summary>
            public const string Unit = "Pa";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "youngsModulus";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Young's modulus E of the rope material (Pa). Polyamide lanyard ≈ 1e8–1e9, steel ≈ 2e11.";
            /// <summary>Exclusive lower bound in Pa.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in Pa (finite; the core also accepts +∞).</summary>
            public const float Max = 1e13f;
            /// <summary>Default in Pa (polyamide lanyard).</summary>
            public const float Default = 1.5e8f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true, allowsPositiveInfinity: true);
        }

        /// <summary>Axial stiffness E·A in newtons; +∞ = inextensible (core only).</summary>
        public static class AxialStiffness
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(AxialStiffness);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Axial stiffness";
            /// <summary>Unit.</summary>
            public const string Unit = "N";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "axialStiffness";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Axial stiffness E·A (N): force per unit strain. Used when the stiffness input is Axial Stiffness.";
            /// <summary>Exclusive lower bound in N.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in N (finite; the core also accepts +∞).</summary>
            public const float Max = 1e12f;
            /// <summary>Default in N: the default E times π·R² of the default radius (1.5e8 Pa · π · (0.008 m)²).</summary>
            public const float Default = 30159f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true, allowsPositiveInfinity: true);
        }

        /// <summary>Material density ρ in kg/m³.</summary>
        public static class Density
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Density);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Density";
            /// <summary>Unit.</summary>
            public const string Unit = "kg/m³";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "density";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Material density ρ (kg/m³); rope mass per metre = ρ·πR². Polyamide ≈ 1140, steel ≈ 7850.";
            /// <summary>Exclusive lower bound in kg/m³.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in kg/m³.</summary>
            public const float Max = 1e5f;
            /// <summary>Default in kg/m³ (polyamide).</summary>
            public const float Default = 1140f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true);
        }

        /// <summary>Mass per unit rest length μ = ρ·π·R² in kg/m (core and lab; the inspector edits ρ).</summary>
        public static class LinearDensity
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(LinearDensity);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Linear density";
            /// <summary>Unit.</summary>
            public const string Unit = "kg/m";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "linearDensity";
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "Rope mass per metre of rest length μ (kg/m); setting it sets ρ = μ/(πR²).";
            /// <summary>Exclusive lower bound in kg/m.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in kg/m.</summary>
            public const float Max = 1e4f;
            /// <summary>Default in kg/m: the default ρ times π·R² of the default radius (1140 · π · (0.008 m)²).</summary>
            public const float Default = 0.22921059f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, false, minExclusive: true);
        }

        /// <summary>Poisson ratio ν (dimensionless); 0.5 keeps the volume.</summary>
        public static class PoissonRatio
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(PoissonRatio);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Poisson ratio";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "poissonRatio";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Poisson ratio ν (dimensionless, −1 to 0.5): how much the rope thins as it stretches. 0.5 keeps the volume; negative values thicken (auxetic).";
            /// <summary>Lower bound.</summary>
            public const float Min = -1f;
            /// <summary>Upper bound.</summary>
            public const float Max = 0.5f;
            /// <summary>Default.</summary>
            public const float Default = 0.3f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>XPBD constraint damping β in seconds.</summary>
        public static class Damping
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Damping);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Damping";
            /// <summary>Unit.</summary>
            public const string Unit = "s";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "damping";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "XPBD constraint damping β (s): removes axial vibration without moving the static sag. 0 = undamped.";
            /// <summary>Lower bound in s.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in s.</summary>
            public const float Max = 10f;
            /// <summary>Default in s.</summary>
            public const float Default = 0.002f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        // ---- Material law (issue 15): plasticity, necking, energy absorber ----------------------------------

        /// <summary>The constitutive law of the segments: elastic, or elastic–plastic with necking.</summary>
        public static class MaterialModel
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(MaterialModel);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Material model";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (elastic or elastic-plastic).</summary>
            public const string Json = "materialModel";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Elastic: the force follows the stretch at any strain (bungee, fitness cord). Elastic-Plastic: yields at the yield strain, keeps a permanent set, necks at the necking strain and softens to zero force at the ultimate strain, where it breaks (lanyard, cable under overload).";
            /// <summary>Default.</summary>
            public const MaterialModelKind Default = MaterialModelKind.Elastic;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Enum, (int)MaterialModelKind.Elastic, (int)MaterialModelKind.ElasticPlastic, (int)Default, Tooltip, Json, true);
        }

        /// <summary>Elastic strain at yield ε_y (dimensionless); the yield force is E·A·ε_y.</summary>
        public static class YieldStrain
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(YieldStrain);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Yield strain";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "yieldStrain";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Elastic-Plastic: strain l/L − 1 (dimensionless) at which the rope yields; the yield force is E·A·ε_y (N). At most the necking strain, below the ultimate strain. Polyamide ≈ 0.1, steel ≈ 0.002.";
            /// <summary>Exclusive lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 1000f;
            /// <summary>Default.</summary>
            public const float Default = 0.1f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true);
        }

        /// <summary>Hardening modulus H in newtons: force gained per unit plastic strain (0 = a plateau).</summary>
        public static class HardeningModulus
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(HardeningModulus);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Hardening modulus";
            /// <summary>Unit.</summary>
            public const string Unit = "N";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "hardeningModulus";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Elastic-Plastic: force gained per unit plastic strain after yield, H (N); 0 = a plateau (the force stops growing). Must not be negative: softening is the neck's.";
            /// <summary>Lower bound in N.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in N.</summary>
            public const float Max = 1e12f;
            /// <summary>Default in N.</summary>
            public const float Default = 5000f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Strain at which the neck forms (the plastic strain localises at the defect; the force peaks there).</summary>
        public static class NeckingStrain
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(NeckingStrain);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Necking strain";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "neckingStrain";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Elastic-Plastic: strain l/L − 1 (dimensionless) on the hardening curve at which the neck forms at the defect and softens (the force peaks here). In [yield strain, ultimate strain).";
            /// <summary>Exclusive lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 1000f;
            /// <summary>Default.</summary>
            public const float Default = 0.45f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true);
        }

        /// <summary>Ultimate strain ε_u of the neck segment (elongation at break): its force has fallen to zero.</summary>
        public static class UltimateStrain
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(UltimateStrain);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Ultimate strain";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "ultimateStrain";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Elastic-Plastic: strain l/L − 1 (dimensionless) of the neck segment at which its force has fallen to zero and the rope breaks (elongation at break). Above the necking strain.";
            /// <summary>Exclusive lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 1000f;
            /// <summary>Default.</summary>
            public const float Default = 0.6f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true);
        }

        /// <summary>An energy absorber (tear webbing) in series with the rope's last segment.</summary>
        public static class EnergyAbsorber
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(EnergyAbsorber);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Energy absorber";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "energyAbsorber";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "An energy absorber (tear webbing) at the end of the rope, in series with its elasticity: it deploys at the plateau force until its deployment length is used, then the webbing's elasticity takes over. EN 355: at most 6 kN with 100 kg.";
            /// <summary>Default.</summary>
            public const bool Default = false;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Bool, 0, 1, 0, Tooltip, Json, true);
        }

        /// <summary>Plateau (deployment) force F_p of the energy absorber in newtons.</summary>
        public static class AbsorberForce
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(AbsorberForce);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Absorber plateau force";
            /// <summary>Unit.</summary>
            public const string Unit = "N";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "absorberForce";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Energy absorber: force (N) at which it tears open and deploys; the arrest force stays at this plateau while it deploys. Typical EN 355 absorbers ≈ 4000 N.";
            /// <summary>Exclusive lower bound in N.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in N.</summary>
            public const float Max = 1e7f;
            /// <summary>Default in N.</summary>
            public const float Default = 4000f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true);
        }

        /// <summary>Largest deployment (tear-out length) of the energy absorber in metres.</summary>
        public static class AbsorberDeployment
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(AbsorberDeployment);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Absorber deployment length";
            /// <summary>Unit.</summary>
            public const string Unit = "m";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "absorberDeployment";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Energy absorber: length (m) it can deploy; once used up, the webbing's elasticity takes over and the force rises again. EN 355 absorbers deploy up to ≈ 1.75 m.";
            /// <summary>Exclusive lower bound in m.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in m.</summary>
            public const float Max = 100f;
            /// <summary>Default in m.</summary>
            public const float Default = 1.75f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Material, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true);
        }

        // ---- Geometry ---------------------------------------------------------------------------------------

        /// <summary>Rest (unstretched) length L in metres.</summary>
        public static class RestLength
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(RestLength);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Rest length";
            /// <summary>Unit.</summary>
            public const string Unit = "m";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "restLength";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Rest (unstretched) length L (m).";
            /// <summary>Lower bound in m.</summary>
            public const float Min = 0.01f;
            /// <summary>Upper bound in m.</summary>
            public const float Max = 10000f;
            /// <summary>Default in m.</summary>
            public const float Default = 2f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Geometry, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Rest radius R of the cross-section in metres.</summary>
        public static class Radius
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Radius);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Radius";
            /// <summary>Unit.</summary>
            public const string Unit = "m";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "radius";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Rest radius R (m) of the rope's cross-section.";
            /// <summary>Exclusive lower bound in m.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in m.</summary>
            public const float Max = 1f;
            /// <summary>Default in m (a 16 mm rope).</summary>
            public const float Default = 0.008f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Geometry, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true);
        }

        /// <summary>Number of segments (particles = segments + 1).</summary>
        public static class SegmentCount
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(SegmentCount);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Segment count";
            /// <summary>Unit (a count).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "segments";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Number of segments (particles = segments + 1). Changing it during Play rebuilds the rope.";
            /// <summary>Lower bound.</summary>
            public const int Min = 1;
            /// <summary>Upper bound.</summary>
            public const int Max = 10000;
            /// <summary>Default.</summary>
            public const int Default = 24;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Geometry, ParameterKind.Int, Min, Max, Default, Tooltip, Json, true);
        }

        // ---- Solver -----------------------------------------------------------------------------------------

        /// <summary>The constraint solver (Gauss–Seidel or exact chain).</summary>
        public static class Solver
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Solver);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Solver";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (in the solver object: exact-chain or gauss-seidel).</summary>
            public const string Json = "method";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Exact Chain solves the whole chain at once each iteration (right stretch under heavy loads); Gauss-Seidel is cheaper per iteration but stretches under heavy loads.";
            /// <summary>Default.</summary>
            public const ConstraintSolverKind Default = ConstraintSolverKind.ExactChain;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Solver, ParameterKind.Enum, (int)ConstraintSolverKind.GaussSeidel, (int)ConstraintSolverKind.ExactChain, (int)Default, Tooltip, Json, true);
        }

        /// <summary>Substeps per host (physics) step.</summary>
        public static class Substeps
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Substeps);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Substeps";
            /// <summary>Unit (a count).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "substeps";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Substeps per physics step (1–1000). More substeps = stiffer, more accurate, slower.";
            /// <summary>Lower bound.</summary>
            public const int Min = 1;
            /// <summary>Upper bound.</summary>
            public const int Max = 1000;
            /// <summary>Default.</summary>
            public const int Default = 8;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Solver, ParameterKind.Int, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Constraint iterations per substep.</summary>
        public static class Iterations
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Iterations);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Iterations";
            /// <summary>Unit (a count).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "iterations";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Constraint iterations per substep (1–1000).";
            /// <summary>Lower bound.</summary>
            public const int Min = 1;
            /// <summary>Upper bound.</summary>
            public const int Max = 1000;
            /// <summary>Default.</summary>
            public const int Default = 1;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Solver, ParameterKind.Int, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Rope (tension only) or rod (bilateral).</summary>
        public static class TensionModel
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(TensionModel);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Tension model";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (in the solver object: tension-only or bilateral).</summary>
            public const string Json = "tension";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Tension Only: a rope pulls but never pushes. Bilateral: a rod that also pushes.";
            /// <summary>Default.</summary>
            public const TensionModelKind Default = TensionModelKind.TensionOnly;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Solver, ParameterKind.Enum, (int)TensionModelKind.TensionOnly, (int)TensionModelKind.Bilateral, (int)Default, Tooltip, Json, true);
        }

        /// <summary>Time integrator of each substep: backward Euler (most robust, dissipative) or BDF2 (second order, low dissipation).</summary>
        public static class Integrator
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Integrator);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Integrator";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (in the solver object: backward-euler or bdf2).</summary>
            public const string Json = "integrator";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Backward Euler: most robust, but damps oscillations (a bounce loses height, a snatch reads low). BDF2: second order, keeps the energy of slow motion, damps only the fastest chain modes.";
            /// <summary>Default: the core's <see cref="HookeRope.Solver.RopeSettings.DefaultIntegrator"/>.</summary>
            public const TimeIntegratorKind Default = HookeRope.Solver.RopeSettings.DefaultIntegrator;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Solver, ParameterKind.Enum, (int)TimeIntegratorKind.BackwardEuler, (int)TimeIntegratorKind.Bdf2, (int)Default, Tooltip, Json, true);
        }

        /// <summary>The Gauss–Seidel kernel: the precise default or the opt-in fused single-precision pass (plain chains only).</summary>
        public static class GaussSeidelKernel
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(GaussSeidelKernel);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Gauss-Seidel kernel";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (none: the lab runs the default kernel).</summary>
            public const string Json = null;
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Gauss-Seidel only. Precise: float positions with sub-float remainders, double velocities, three passes per substep. Fused Single: one float pass per substep, about 3x fewer instructions, no sub-float remainders (tensions within 0.05% of Precise where Gauss-Seidel converges, coarser far from the rope's origin); used only with Backward Euler and no colliders, drag, compliant pins or plastic material, else Precise runs.";
            /// <summary>Default: the precise kernel.</summary>
            public const GaussSeidelKernelKind Default = GaussSeidelKernelKind.Precise;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Solver, ParameterKind.Enum, (int)GaussSeidelKernelKind.Precise, (int)GaussSeidelKernelKind.FusedSingle, (int)Default, Tooltip, Json, true);
        }

        /// <summary>Gravity acceleration acting on the rope in m/s²; each component finite.</summary>
        public static class Gravity
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Gravity);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Gravity";
            /// <summary>Unit.</summary>
            public const string Unit = "m/s²";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "gravity";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Gravity acting on the rope (m/s²).";
            /// <summary>Lower bound of each component in m/s².</summary>
            public const float Min = -1000f;
            /// <summary>Upper bound of each component in m/s².</summary>
            public const float Max = 1000f;
            /// <summary>Default x component in m/s².</summary>
            public const float DefaultX = 0f;
            /// <summary>Default y component in m/s² (standard gravity, down).</summary>
            public const float DefaultY = -9.81f;
            /// <summary>Default z component in m/s².</summary>
            public const float DefaultZ = 0f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Solver, ParameterKind.Vector, Min, Max, double.NaN, Tooltip, Json, true, defaultComponents: new[] { DefaultX, DefaultY, DefaultZ });
        }

        // ---- Attachments and collisions ---------------------------------------------------------------------

        /// <summary>Compliance of the Transform (kinematic) attachments in m/N; 0 = rigid.</summary>
        public static class AttachmentCompliance
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(AttachmentCompliance);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Attachment compliance";
            /// <summary>Unit.</summary>
            public const string Unit = "m/N";
            /// <summary>Lab JSON name (in an attachment object).</summary>
            public const string Json = "compliance";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Compliance of the Transform attachments (m/N); 0 = rigid.";
            /// <summary>Lower bound in m/N.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in m/N.</summary>
            public const float Max = 1f;
            /// <summary>Default in m/N (rigid).</summary>
            public const float Default = 0f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Attachments, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Coulomb friction coefficient μ between rope and colliders (dimensionless).</summary>
        public static class Friction
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Friction);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Friction";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (in a collider object).</summary>
            public const string Json = "friction";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Coulomb friction coefficient μ between rope and colliders (dimensionless, 0–2).";
            /// <summary>Lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 10f;
            /// <summary>Default.</summary>
            public const float Default = 0.3f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Collisions, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        // ---- Drag -------------------------------------------------------------------------------------------

        /// <summary>Viscous drag coefficient c in N·s/m²: a force −c·(v − wind) per metre of rope.</summary>
        public static class ViscousDrag
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(ViscousDrag);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Viscous drag";
            /// <summary>Unit.</summary>
            public const string Unit = "N·s/m²";
            /// <summary>Lab JSON name (in the drag object).</summary>
            public const string Json = "viscousDrag";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Viscous drag per metre of rope (N·s/m²): a force −c·v per metre on the rope's velocity relative to the air. A swing decays as exp(−c·t/(2μ)), μ = mass per metre; a rope falls at most at μ·g/c. 0 = off (costs nothing).";
            /// <summary>Lower bound in N·s/m².</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in N·s/m².</summary>
            public const float Max = 1e4f;
            /// <summary>Default in N·s/m² (off).</summary>
            public const float Default = 0f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Drag, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Drag coefficient C_d of the quadratic air drag across the rope (dimensionless).</summary>
        public static class DragCoefficient
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(DragCoefficient);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Drag coefficient";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (in the drag object).</summary>
            public const string Json = "dragCoefficient";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Drag coefficient C_d of the air drag across the rope (dimensionless): ½·ρ·C_d·2R·|v⊥|·v⊥ per metre on the velocity across the rope relative to the air. About 1.0–1.2 for a rope in air. 0 = off.";
            /// <summary>Lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 10f;
            /// <summary>Default (off).</summary>
            public const float Default = 0f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Drag, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Skin-friction coefficient C_f of the axial air drag along the rope (dimensionless).</summary>
        public static class SkinFriction
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(SkinFriction);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Skin friction coefficient";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (in the drag object).</summary>
            public const string Json = "skinFriction";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Skin-friction coefficient C_f of the air drag along the rope (dimensionless): ½·ρ·C_f·2πR·|v∥|·v∥ per metre on the velocity along the rope relative to the air. About 0.01; small beside the drag across. 0 = off.";
            /// <summary>Lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 1f;
            /// <summary>Default (off).</summary>
            public const float Default = 0f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Drag, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Density ρ of the air (or fluid) the rope moves through, in kg/m³.</summary>
        public static class AirDensity
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(AirDensity);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Air density";
            /// <summary>Unit.</summary>
            public const string Unit = "kg/m³";
            /// <summary>Lab JSON name (in the drag object).</summary>
            public const string Json = "airDensity";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Density ρ of the air the rope moves through (kg/m³): 1.2 at sea level, 1000 for water. Scales the drag across the rope (C_d) and the skin friction (C_f).";
            /// <summary>Lower bound in kg/m³.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in kg/m³.</summary>
            public const float Max = 1e4f;
            /// <summary>Default in kg/m³ (air at sea level, 20 °C).</summary>
            public const float Default = 1.2f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Drag, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Velocity of the air (wind) in m/s, world coordinates; each component finite.</summary>
        public static class Wind
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Wind);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Wind";
            /// <summary>Unit.</summary>
            public const string Unit = "m/s";
            /// <summary>Lab JSON name (in the drag object).</summary>
            public const string Json = "wind";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Velocity of the air in world coordinates (m/s). The drag acts on the rope's velocity relative to it; no drag coefficient, no effect.";
            /// <summary>Lower bound of each component in m/s.</summary>
            public const float Min = -1000f;
            /// <summary>Upper bound of each component in m/s.</summary>
            public const float Max = 1000f;
            /// <summary>Default x component in m/s.</summary>
            public const float DefaultX = 0f;
            /// <summary>Default y component in m/s.</summary>
            public const float DefaultY = 0f;
            /// <summary>Default z component in m/s.</summary>
            public const float DefaultZ = 0f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Drag, ParameterKind.Vector, Min, Max, double.NaN, Tooltip, Json, true, defaultComponents: new[] { DefaultX, DefaultY, DefaultZ });
        }

        // ---- Radius -----------------------------------------------------------------------------------------

        /// <summary>Poisson thinning on: the radius follows the strain (eq. 16).</summary>
        public static class PoissonThinning
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(PoissonThinning);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Poisson thinning";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "poissonThinning";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Thin the rope as it stretches (Poisson ratio). Off costs nothing; the radius stays R.";
            /// <summary>Default.</summary>
            public const bool Default = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Radius, ParameterKind.Bool, 0, 1, 1, Tooltip, Json, true);
        }

        /// <summary>Necking on: a neck forms at the defect once the radius falls below r_min.</summary>
        public static class Necking
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Necking);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Necking";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "necking";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Form a neck at the defect once the radius falls below r_min. Needs the radius model.";
            /// <summary>Default.</summary>
            public const bool Default = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Radius, ParameterKind.Bool, 0, 1, 1, Tooltip, Json, true);
        }

        /// <summary>The neck model used when necking is on (Paper = 1, Zone = 2).</summary>
        public static class NeckMode
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(NeckMode);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Neck mode";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (zone or paper).</summary>
            public const string Json = "neckMode";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Zone: a neck over a few diameters around the defect that deepens smoothly (default). Paper: Chen et al.'s hyperbola over the whole length (eq. 18); at onset the waist jumps to about 2·r_min²/l.";
            /// <summary>Default.</summary>
            public const NeckModeKind Default = NeckModeKind.Zone;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Radius, ParameterKind.Enum, (int)NeckModeKind.Paper, (int)NeckModeKind.Zone, (int)Default, Tooltip, Json, true);
        }

        /// <summary>Neck onset radius r_min as a fraction of the rest radius R (dimensionless).</summary>
        public static class NeckRadiusFraction
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(NeckRadiusFraction);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Neck radius fraction r_min/R";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "neckRadiusFraction";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Neck onset radius r_min as a fraction of the rest radius R (dimensionless, 0.01–1).";
            /// <summary>Lower bound.</summary>
            public const float Min = 0.01f;
            /// <summary>Upper bound.</summary>
            public const float Max = 1f;
            /// <summary>Default.</summary>
            public const float Default = 0.75f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Radius, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Defect position as a fraction of the rest length from the start (dimensionless).</summary>
        public static class DefectPosition
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(DefectPosition);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Defect position";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "defectPosition";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Where the material defect sits, as a fraction of the rest length from the start, strictly between 0 and 1 (the ends are attachments, not material). The neck and the break form there.";
            /// <summary>Lower bound (exclusive).</summary>
            public const float Min = 0f;
            /// <summary>The lower bound is excluded.</summary>
            public const bool MinExclusive = true;
            /// <summary>Upper bound (exclusive).</summary>
            public const float Max = 1f;
            /// <summary>The upper bound is excluded.</summary>
            public const bool MaxExclusive = true;
            /// <summary>Default (the middle).</summary>
            public const float Default = 0.5f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Radius, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true,
                minExclusive: MinExclusive, maxExclusive: MaxExclusive);
        }

        /// <summary>Zone mode: rest length of the neck zone in rope diameters 2R (dimensionless).</summary>
        public static class NeckZoneDiameters
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(NeckZoneDiameters);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Neck zone diameters";
            /// <summary>Unit (rope diameters).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "neckZoneDiameters";
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "Zone mode: rest length of the neck zone in rope diameters 2R, centred on the defect.";
            /// <summary>Lower bound.</summary>
            public const float Min = 0.5f;
            /// <summary>Upper bound.</summary>
            public const float Max = 1000f;
            /// <summary>Default (a zone of 8·R).</summary>
            public const float Default = 4f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Radius, ParameterKind.Float, Min, Max, Default, Tooltip, Json, false);
        }

        /// <summary>Zone mode: strain beyond onset over which the neck deepens to the full hyperbola (dimensionless).</summary>
        public static class NeckGrowthStrain
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(NeckGrowthStrain);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Neck growth strain";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "neckGrowthStrain";
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "Zone mode: strain beyond onset over which the neck deepens from zero to the full hyperbola.";
            /// <summary>Exclusive lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 100f;
            /// <summary>Default.</summary>
            public const float Default = 0.2f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Radius, ParameterKind.Float, Min, Max, Default, Tooltip, Json, false, minExclusive: true);
        }

        /// <summary>A segment shorter than its rest length keeps the rest radius.</summary>
        public static class SlackKeepsRestRadius
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(SlackKeepsRestRadius);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Slack keeps rest radius";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "slackKeepsRestRadius";
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "A segment shorter than its rest length keeps the rest radius: a tension-only rope goes slack instead of being compressed.";
            /// <summary>Default.</summary>
            public const bool Default = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Radius, ParameterKind.Bool, 0, 1, 1, Tooltip, Json, false);
        }

        // ---- Fracture ---------------------------------------------------------------------------------------

        /// <summary>Fracture on: the rope can break at the defect.</summary>
        public static class Fracture
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Fracture);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Fracture";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "fracture";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Let the rope break. Off costs nothing.";
            /// <summary>Default.</summary>
            public const bool Default = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Fracture, ParameterKind.Bool, 0, 1, 1, Tooltip, Json, true);
        }

        /// <summary>Strain l/L − 1 of the defect segment at which the rope breaks (dimensionless).</summary>
        public static class BreakStrain
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(BreakStrain);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Break strain";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "breakStrain";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Break threshold: the strain l/L − 1 (dimensionless) of the defect segment at which the rope breaks.";
            /// <summary>Exclusive lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 1000f;
            /// <summary>Default.</summary>
            public const float Default = 0.6f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Fracture, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true, minExclusive: true);
        }

        /// <summary>The rope also breaks when the neck radius falls below this fraction of R (dimensionless; 0 = off; needs necking).</summary>
        public static class BreakRadiusFraction
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(BreakRadiusFraction);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Break radius fraction";
            /// <summary>Unit (dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "breakRadiusFraction";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "The rope also breaks when the neck radius falls below this fraction of R (dimensionless, 0–0.99; 0 = off). Needs necking.";
            /// <summary>Lower bound.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 0.99f;
            /// <summary>Default.</summary>
            public const float Default = 0.25f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Fracture, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        // ---- Mesh -------------------------------------------------------------------------------------------

        /// <summary>Vertices around the tube.</summary>
        public static class RadialSegments
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(RadialSegments);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Radial segments";
            /// <summary>Unit (a count).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "radialSegments";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Vertices around the tube (3–64). 8 is cheap, 16 smooth, 32 for close-ups.";
            /// <summary>Lower bound.</summary>
            public const int Min = 3;
            /// <summary>Upper bound.</summary>
            public const int Max = 64;
            /// <summary>Default.</summary>
            public const int Default = 12;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Int, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>How far the adaptive rings let the drawn surface leave the smooth tube along the rope.</summary>
        public static class RingTolerance
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(RingTolerance);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Ring tolerance";
            /// <summary>Unit (a multiple of the polygon's depth R·(1 − cos π/N), dimensionless).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "ringTolerance";
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "How far the drawn surface may leave the smooth tube along the rope, as a multiple of the polygon's own depth around it, R·(1 − cos π/N) (dimensionless, 1–16). 1 = as round along as around; 2 draws about 30 % fewer rings on a bent rope, for scenes with many ropes.";
            /// <summary>Lower bound.</summary>
            public const float Min = 1f;
            /// <summary>Upper bound.</summary>
            public const float Max = 16f;
            /// <summary>Default.</summary>
            public const float Default = 1f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>View distance beyond which the ring tolerance grows with the distance (ViewDetail).</summary>
        public static class DetailDistance
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(DetailDistance);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Detail distance";
            /// <summary>Unit.</summary>
            public const string Unit = "m";
            /// <summary>Lab JSON name (none: the lab has no viewer).</summary>
            public const string Json = null;
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Distance from the View Point (m) up to which the rope draws at its Ring Tolerance; beyond it the along-rope error allowed grows with the distance (twice as far: twice the error), and from 4.4 times as far an unbroken rope draws half its sides, so the detail seen from the viewer stays the same. 0 = off.";
            /// <summary>Lower bound (0: off).</summary>
            public const float Min = 0f;
            /// <summary>Upper bound.</summary>
            public const float Max = 1e4f;
            /// <summary>Default (off).</summary>
            public const float Default = 0f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Float, Min, Max, Default, Tooltip, Json, true);
        }

        /// <summary>Rings per rope segment along the smooth curve (core only).</summary>
        public static class RingsPerSegment
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(RingsPerSegment);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Rings per segment";
            /// <summary>Unit (a count).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (none).</summary>
            public const string Json = null;
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "Rings per rope segment along the smooth curve.";
            /// <summary>Lower bound.</summary>
            public const int Min = 1;
            /// <summary>Upper bound.</summary>
            public const int Max = 64;
            /// <summary>Default.</summary>
            public const int Default = 4;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Int, Min, Max, Default, Tooltip, Json, false);
        }

        /// <summary>Rings placed by need instead of RingsPerSegment in every segment (core only).</summary>
        public static class AdaptiveRings
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(AdaptiveRings);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Adaptive rings";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (none).</summary>
            public const string Json = null;
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "Place the tube's rings by need: one per segment where the rope is straight, more where it bends, the neck's stations while it necks, so the drawn surface stays within the polygon's own error of the smooth tube. Off: RingsPerSegment rings in every segment.";
            /// <summary>Default.</summary>
            public const bool Default = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Bool, 0, 1, 1, Tooltip, Json, false);
        }

        /// <summary>Texture v per metre of rest arc length in 1/m (core only).</summary>
        public static class VPerMetre
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(VPerMetre);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Texture v per metre";
            /// <summary>Unit.</summary>
            public const string Unit = "1/m";
            /// <summary>Lab JSON name (none).</summary>
            public const string Json = null;
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "Texture v per metre of rest arc length (1/m); the texture stretches with the material.";
            /// <summary>Exclusive lower bound in 1/m.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound in 1/m.</summary>
            public const float Max = 10000f;
            /// <summary>Default in 1/m.</summary>
            public const float Default = 10f;
            /// <summary>The lower bound is exclusive.</summary>
            public const bool MinExclusive = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Float, Min, Max, Default, Tooltip, Json, false, minExclusive: true);
        }

        /// <summary>Close the two intact ends with flat caps (core only).</summary>
        public static class CapEnds
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(CapEnds);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Cap ends";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (none).</summary>
            public const string Json = null;
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "Close the two intact ends of the rope with flat caps (the intact mesh is then watertight). Broken ends are always closed.";
            /// <summary>Default.</summary>
            public const bool Default = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Bool, 0, 1, 1, Tooltip, Json, false);
        }

        /// <summary>Seed of the burr strands at broken ends (core <c>BurrSettings.Seed</c>, lab <c>seed</c>).</summary>
        public static class BurrSeed
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(BurrSeed);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Burr seed";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name.</summary>
            public const string Json = "seed";
            /// <summary>Tooltip.</summary>
            public const string Tooltip = "Seed of the burr strand lengths and directions; the same seed gives the same burr.";
            /// <summary>Lower bound.</summary>
            public const int Min = 0;
            /// <summary>Upper bound.</summary>
            public const int Max = int.MaxValue;
            /// <summary>Default.</summary>
            public const int Default = 1;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Int, Min, Max, Default, Tooltip, Json, false);
        }

        /// <summary>Draw the burr strands with a copy of the tube material carrying the procedural burr texture (renderer).</summary>
        public static class BurrTexture
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(BurrTexture);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Burr texture";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (none).</summary>
            public const string Json = null;
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "When the renderer has no second material: draw the burr strands (opaque geometry) with a copy of the tube material carrying the procedural burr texture. Off: the strands use the tube material.";
            /// <summary>Default.</summary>
            public const bool Default = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Bool, 0, 1, 1, Tooltip, Json, true);
        }

        /// <summary>Write vertex tangents (renderer): 48-byte vertices with, 32-byte <see cref="HookeRope.Geometry.LeanTubeVertex"/> without.</summary>
        public static class Tangents
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Tangents);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Tangents";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (none).</summary>
            public const string Json = null;
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Write vertex tangents (48 bytes a vertex). Only normal-mapped materials read them: off, the mesh has position, normal and uv (32 bytes), a third less to write and upload every frame, the same surface.";
            /// <summary>Default.</summary>
            public const bool Default = true;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Bool, 0, 1, 1, Tooltip, Json, true);
        }

        /// <summary>Colour of the generated tube material (renderer), RGBA in [0, 1].</summary>
        public static class Color
        {
            /// <summary>Property name.</summary>
            public const string Name = nameof(Color);
            /// <summary>Label used in messages.</summary>
            public const string Label = "Colour";
            /// <summary>Unit (none).</summary>
            public const string Unit = "";
            /// <summary>Lab JSON name (none).</summary>
            public const string Json = null;
            /// <summary>Inspector tooltip.</summary>
            public const string Tooltip = "Colour of the generated tube material (used only when the renderer has no material). Safety orange by default.";
            /// <summary>Lower bound of each channel.</summary>
            public const float Min = 0f;
            /// <summary>Upper bound of each channel.</summary>
            public const float Max = 1f;
            /// <summary>Default red channel (safety orange).</summary>
            public const float DefaultR = 0.93f;
            /// <summary>Default green channel.</summary>
            public const float DefaultG = 0.5f;
            /// <summary>Default blue channel.</summary>
            public const float DefaultB = 0.12f;
            /// <summary>Default alpha channel.</summary>
            public const float DefaultA = 1f;
            /// <summary>The table row.</summary>
            public static readonly ParameterInfo Row = new ParameterInfo(Name, Label, Unit, ParameterGroup.Mesh, ParameterKind.Color, Min, Max, double.NaN, Tooltip, Json, true, defaultComponents: new[] { DefaultR, DefaultG, DefaultB, DefaultA });
        }

        // ---- The table and its checks -----------------------------------------------------------------------

        /// <summary>Every row, grouped in inspector order.</summary>
        public static IReadOnlyList<ParameterInfo> All { get; } = new[]
        {
            StiffnessInput.Row, YoungsModulus.Row, AxialStiffness.Row, Density.Row, LinearDensity.Row, PoissonRatio.Row, Damping.Row,
            MaterialModel.Row, YieldStrain.Row, HardeningModulus.Row, NeckingStrain.Row, UltimateStrain.Row, EnergyAbsorber.Row, AbsorberForce.Row, AbsorberDeployment.Row,
            RestLength.Row, Radius.Row, SegmentCount.Row,
            Solver.Row, Substeps.Row, Iterations.Row, TensionModel.Row, Integrator.Row, GaussSeidelKernel.Row, Gravity.Row,
            AttachmentCompliance.Row,
            Friction.Row,
            ViscousDrag.Row, DragCoefficient.Row, SkinFriction.Row, AirDensity.Row, Wind.Row,
            PoissonThinning.Row, Necking.Row, NeckMode.Row, NeckRadiusFraction.Row, DefectPosition.Row, NeckZoneDiameters.Row, NeckGrowthStrain.Row, SlackKeepsRestRadius.Row,
            Fracture.Row, BreakStrain.Row, BreakRadiusFraction.Row,
            RadialSegments.Row, RingTolerance.Row, DetailDistance.Row, RingsPerSegment.Row, AdaptiveRings.Row, VPerMetre.Row, CapEnds.Row, BurrSeed.Row, BurrTexture.Row, Tangents.Row, Color.Row,
        };

        /// <summary>The row named <paramref name="name"/> (ordinal), or null.</summary>
        public static ParameterInfo Find(string name)
        {
            var all = All;
            for (int i = 0; i < all.Count; i++)
                if (string.Equals(all[i].Name, name, StringComparison.Ordinal)) return all[i];
            return null;
        }

        /// <summary>True when <paramref name="value"/> lies in the row's range (+∞ only where the row allows it; never NaN).</summary>
        public static bool Contains(ParameterInfo row, double value)
        {
            if (row == null) throw new ArgumentNullException(nameof(row));
            if (double.IsNaN(value)) return false;
            if (double.IsPositiveInfinity(value)) return row.AllowsPositiveInfinity;
            return (row.MinExclusive ? value > row.Min : value >= row.Min) && (row.MaxExclusive ? value < row.Max : value <= row.Max);
        }

        /// <summary>
        /// Returns <paramref name="value"/>, or throws <see cref="ArgumentOutOfRangeException"/> whose message names the
        /// parameter, its range and unit, e.g. "RestLength must be in [0.01, 10000] m.".
        /// </summary>
        public static float Check(float value, ParameterInfo row)
        {
            if (!Contains(row, value)) throw OutOfRange(row, value);
            return value;
        }

        /// <summary>Integer variant of <see cref="Check(float, ParameterInfo)"/>.</summary>
        public static int Check(int value, ParameterInfo row)
        {
            if (!Contains(row, value)) throw OutOfRange(row, value);
            return value;
        }

        /// <summary>
        /// Clamps <paramref name="value"/> into the row's finite range for the inspector: above Max (or +∞) becomes Max,
        /// below Min becomes Min, and NaN or a value at or beyond an exclusive bound becomes the row's Default. Returns the
        /// message to log when it had to change the value (naming the label, range and unit), else null.
        /// </summary>
        public static string Clamp(ref float value, ParameterInfo row)
        {
            if (row == null) throw new ArgumentNullException(nameof(row));
            float before = value;
            if (float.IsNaN(value)) value = (float)row.Default;
            else if (row.MaxExclusive ? value >= row.Max : value > row.Max) value = row.MaxExclusive ? (float)row.Default : (float)row.Max;
            else if (row.MinExclusive ? value <= row.Min : value < row.Min) value = row.MinExclusive ? (float)row.Default : (float)row.Min;
            if (before.Equals(value)) return null;
            return Message(row, Format(before), Format(value));
        }

        /// <summary>Integer variant of <see cref="Clamp(ref float, ParameterInfo)"/>.</summary>
        public static string Clamp(ref int value, ParameterInfo row)
        {
            if (row == null) throw new ArgumentNullException(nameof(row));
            int before = value;
            if (row.MaxExclusive ? value >= row.Max : value > row.Max) value = row.MaxExclusive ? (int)row.Default : (int)row.Max;
            else if (row.MinExclusive ? value <= row.Min : value < row.Min) value = row.MinExclusive ? (int)row.Default : (int)row.Min;
            if (before == value) return null;
            return Message(row, before.ToString(CultureInfo.InvariantCulture), value.ToString(CultureInfo.InvariantCulture));
        }

        internal static string FormatRange(ParameterInfo row)
        {
            string min = row.Kind == ParameterKind.Int ? ((long)row.Min).ToString(CultureInfo.InvariantCulture) : Format((float)row.Min);
            string max = row.Kind == ParameterKind.Int ? ((long)row.Max).ToString(CultureInfo.InvariantCulture) : Format((float)row.Max);
            if (row.AllowsPositiveInfinity) max += " or +inf";
            return (row.MinExclusive ? "(" : "[") + min + ", " + max + (row.MaxExclusive ? ")" : "]") + Suffix(row.Unit);
        }

        static ArgumentOutOfRangeException OutOfRange(ParameterInfo row, object value) =>
            new ArgumentOutOfRangeException(row.Name, value, row.Name + " must be in " + FormatRange(row) + ".");

        static string Message(ParameterInfo row, string before, string after) =>
            row.Label + " = " + before + Suffix(row.Unit) + " is outside " + FormatRange(row) + "; clamped to " + after + Suffix(row.Unit) + ".";

        static string Format(float value) => value.ToString(CultureInfo.InvariantCulture);

        static string Suffix(string unit) => string.IsNullOrEmpty(unit) ? "" : " " + unit;
    }
}
