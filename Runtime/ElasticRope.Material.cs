using System;
using HookeRope.Solver;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// The material law of <see cref="ElasticRope"/> (issue 15): elastic or elastic–plastic with necking, and the energy
    /// absorber. Serialized fields with ranges, defaults and tooltips from <see cref="RopeParameters"/>, validated properties,
    /// OnValidate's clamp, the copy into the core settings, the read-outs and the quasi-static force–elongation curve the
    /// inspector previews. All of it applies live at the next step.
    /// </summary>
    public sealed partial class ElasticRope
    {
        // ---- Material law ---------------------------------------------------------------------------------
        [SerializeField, Tooltip(RopeParameters.MaterialModel.Tooltip)]
        MaterialModel m_MaterialModel = RopeParameters.MaterialModel.Default;

        [SerializeField, Min(RopeParameters.YieldStrain.Min), Tooltip(RopeParameters.YieldStrain.Tooltip)]
        float m_YieldStrain = RopeParameters.YieldStrain.Default;

        [SerializeField, Min(RopeParameters.HardeningModulus.Min), Tooltip(RopeParameters.HardeningModulus.Tooltip)]
        float m_HardeningModulus = RopeParameters.HardeningModulus.Default;

        [SerializeField, Min(RopeParameters.NeckingStrain.Min), Tooltip(RopeParameters.NeckingStrain.Tooltip)]
        float m_NeckingStrain = RopeParameters.NeckingStrain.Default;

        [SerializeField, Min(RopeParameters.UltimateStrain.Min), Tooltip(RopeParameters.UltimateStrain.Tooltip)]
        float m_UltimateStrain = RopeParameters.UltimateStrain.Default;

        [SerializeField, Tooltip(RopeParameters.EnergyAbsorber.Tooltip)]
        bool m_EnergyAbsorber = RopeParameters.EnergyAbsorber.Default;

        [SerializeField, Min(RopeParameters.AbsorberForce.Min), Tooltip(RopeParameters.AbsorberForce.Tooltip)]
        float m_AbsorberForce = RopeParameters.AbsorberForce.Default;

        [SerializeField, Min(RopeParameters.AbsorberDeployment.Min), Tooltip(RopeParameters.AbsorberDeployment.Tooltip)]
        float m_AbsorberDeployment = RopeParameters.AbsorberDeployment.Default;

        // ---- Properties (validated; changes apply at the next step) ----------------------------------------
        /// <summary>
        /// The segments' constitutive law: elastic, or elastic–plastic (yield, permanent set, necking, break at the ultimate
        /// strain). Switching to elastic–plastic checks yield strain ≤ necking strain &lt; ultimate strain and throws an
        /// <see cref="ArgumentOutOfRangeException"/> naming the first value out of order.
        /// </summary>
        public MaterialModel MaterialModel
        {
            get => m_MaterialModel;
            set
            {
                if (!RopeParameters.Contains(RopeParameters.MaterialModel.Row, (int)value))
                    throw new ArgumentOutOfRangeException(nameof(MaterialModel), value, "MaterialModel must be Elastic or ElasticPlastic.");
                if (value == MaterialModel.ElasticPlastic) new RopeSettings().SetPlasticity(m_YieldStrain, m_HardeningModulus, m_NeckingStrain, m_UltimateStrain);
                m_MaterialModel = value;
                ApplySettings();
            }
        }

        /// <summary>Elastic–plastic: yield strain ε_y (dimensionless), range <see cref="RopeParameters.YieldStrain"/>; with the plastic material at most the necking strain and below the ultimate strain. Yield force E·A·ε_y.</summary>
        public float YieldStrain { get => m_YieldStrain; set => SetPlastic(ref m_YieldStrain, value, RopeParameters.YieldStrain.Row); }

        /// <summary>Elastic–plastic: hardening modulus H (N), range <see cref="RopeParameters.HardeningModulus"/>: force gained per unit plastic strain; 0 = a plateau; negative throws.</summary>
        public float HardeningModulus { get => m_HardeningModulus; set => SetLive(ref m_HardeningModulus, value, RopeParameters.HardeningModulus.Row); }

        /// <summary>Elastic–plastic: strain at which the neck forms at the defect (dimensionless), range <see cref="RopeParameters.NeckingStrain"/>; with the plastic material in [yield strain, ultimate strain).</summary>
        public float NeckingStrain { get => m_NeckingStrain; set => SetPlastic(ref m_NeckingStrain, value, RopeParameters.NeckingStrain.Row); }

        /// <summary>Elastic–plastic: strain of the neck at which its force is zero and the rope breaks (dimensionless), range <see cref="RopeParameters.UltimateStrain"/>; with the plastic material above the necking strain.</summary>
        public float UltimateStrain { get => m_UltimateStrain; set => SetPlastic(ref m_UltimateStrain, value, RopeParameters.UltimateStrain.Row); }

        /// <summary>An energy absorber (tear webbing) in series with the rope's last segment, at the end attachment.</summary>
        public bool EnergyAbsorber { get => m_EnergyAbsorber; set { m_EnergyAbsorber = value; ApplySettings(); } }

        /// <summary>Energy absorber: plateau (deployment) force F_p (N), range <see cref="RopeParameters.AbsorberForce"/>; ≤ 0 throws.</summary>
        public float AbsorberForce { get => m_AbsorberForce; set => SetLive(ref m_AbsorberForce, value, RopeParameters.AbsorberForce.Row); }

        /// <summary>Energy absorber: largest deployment (m), range <see cref="RopeParameters.AbsorberDeployment"/>.</summary>
        public float AbsorberDeployment { get => m_AbsorberDeployment; set => SetLive(ref m_AbsorberDeployment, value, RopeParameters.AbsorberDeployment.Row); }

        /// <summary>
        /// Sets the whole plastic law at once (strains dimensionless, <paramref name="hardening"/> in N) and switches to
        /// elastic–plastic; checks the ranges and the order yield ≤ necking &lt; ultimate, and changes nothing when one fails.
        /// </summary>
        public void SetPlasticity(float yield, float hardening, float necking, float ultimate)
        {
            new RopeSettings().SetPlasticity(yield, hardening, necking, ultimate);
            m_YieldStrain = yield;
            m_HardeningModulus = hardening;
            m_NeckingStrain = necking;
            m_UltimateStrain = ultimate;
            m_MaterialModel = MaterialModel.ElasticPlastic;
            ApplySettings();
        }

        /// <summary>
        /// The energy-absorber preset: the absorber on with the plateau force <paramref name="plateauForce"/> (N) and the
        /// deployment length <paramref name="deploymentLength"/> (m); the defaults are a typical EN 355 absorber (4 kN, 1.75 m).
        /// </summary>
        public void UseEnergyAbsorber(float plateauForce = RopeParameters.AbsorberForce.Default, float deploymentLength = RopeParameters.AbsorberDeployment.Default)
        {
            RopeParameters.Check(plateauForce, RopeParameters.AbsorberForce.Row);
            RopeParameters.Check(deploymentLength, RopeParameters.AbsorberDeployment.Row);
            m_AbsorberForce = plateauForce;
            m_AbsorberDeployment = deploymentLength;
            m_EnergyAbsorber = true;
            ApplySettings();
        }

        // ---- Read-outs ------------------------------------------------------------------------------------
        /// <summary>Permanent set (m): Σ (L_p − L) over the intact segments, the absorber's deployment included; 0 before the build.</summary>
        public float PlasticElongation => (float)(_simulation?.Readouts.PlasticElongation ?? 0.0);

        /// <summary>How far the energy absorber has deployed (m); 0 without one or before the build.</summary>
        public float AbsorberDeployed => (float)(_simulation?.Readouts.AbsorberDeployment ?? 0.0);

        /// <summary>Plastic work (J): the energy the permanent set, the neck and the absorber took; 0 before the build.</summary>
        public float PlasticWork => (float)(_simulation?.Readouts.PlasticWork ?? 0.0);

        /// <summary>
        /// The quasi-static force–elongation curve of the current settings (the inspector's preview): the material law, the
        /// absorber, the rest length, E·A and the segment count; an elastic end runs to the break strain (fracture on) or to
        /// 100 % strain.
        /// </summary>
        public ForceElongationCurve ForceElongationCurve()
        {
            var settings = new RopeSettings();
            WriteSettings(settings);
            settings.SegmentCount = m_SegmentCount;
            return HookeRope.Solver.ForceElongationCurve.Of(settings, m_Fracture ? m_BreakStrain : 1.0);
        }

        // ---- Validation and the copy into the core --------------------------------------------------------
        /// <summary>A strain of the plastic law: the table check, then (plastic material only) the order with the other two.</summary>
        void SetPlastic(ref float field, float value, ParameterInfo row)
        {
            RopeParameters.Check(value, row);
            if (m_MaterialModel == MaterialModel.ElasticPlastic)
            {
                var probe = new RopeSettings();
                probe.SetPlasticity(m_YieldStrain, m_HardeningModulus, m_NeckingStrain, m_UltimateStrain);
                if (row == RopeParameters.YieldStrain.Row) probe.YieldStrain = value;
                else if (row == RopeParameters.NeckingStrain.Row) probe.NeckingStrain = value;
                else probe.UltimateStrain = value;
            }
            field = value;
            ApplySettings();
        }

        /// <summary>
        /// OnValidate's clamp of the material fields (and at every build): each into its table range; with the plastic
        /// material the order yield ≤ necking &lt; ultimate restored by raising the later values, with one warning each.
        /// </summary>
        void ClampMaterialFields()
        {
            Report(RopeParameters.Clamp(ref m_YieldStrain, RopeParameters.YieldStrain.Row));
            Report(RopeParameters.Clamp(ref m_HardeningModulus, RopeParameters.HardeningModulus.Row));
            Report(RopeParameters.Clamp(ref m_NeckingStrain, RopeParameters.NeckingStrain.Row));
            Report(RopeParameters.Clamp(ref m_UltimateStrain, RopeParameters.UltimateStrain.Row));
            Report(RopeParameters.Clamp(ref m_AbsorberForce, RopeParameters.AbsorberForce.Row));
            Report(RopeParameters.Clamp(ref m_AbsorberDeployment, RopeParameters.AbsorberDeployment.Row));
            if (!RopeParameters.Contains(RopeParameters.MaterialModel.Row, (int)m_MaterialModel))
            {
                m_MaterialModel = RopeParameters.MaterialModel.Default;
                Report("Material model must be Elastic or Elastic Plastic; set to Elastic.");
            }
            if (m_MaterialModel != MaterialModel.ElasticPlastic) return;
            if (m_NeckingStrain < m_YieldStrain)
            {
                Report("Necking strain " + m_NeckingStrain + " is below the yield strain " + m_YieldStrain + "; raised to it.");
                m_NeckingStrain = m_YieldStrain;
            }
            if (!(m_UltimateStrain > m_NeckingStrain))
            {
                float raised = Math.Min(RopeParameters.UltimateStrain.Max, Math.Max(m_NeckingStrain * 1.25f, m_NeckingStrain + 0.01f));
                Report("Ultimate strain " + m_UltimateStrain + " is not above the necking strain " + m_NeckingStrain + "; raised to " + raised + ".");
                m_UltimateStrain = raised;
                if (!(m_UltimateStrain > m_NeckingStrain)) m_MaterialModel = MaterialModel.Elastic;   // all three at the table's maximum
            }
        }

        /// <summary>Writes the material law and the absorber into <paramref name="settings"/> (whole-law setters: no transient out-of-order state).</summary>
        void WriteMaterialSettings(RopeSettings settings)
        {
            if (m_MaterialModel == MaterialModel.ElasticPlastic)
            {
                settings.SetPlasticity(m_YieldStrain, m_HardeningModulus, m_NeckingStrain, m_UltimateStrain);
            }
            else
            {
                settings.MaterialModel = MaterialModel.Elastic;
                settings.YieldStrain = m_YieldStrain;
                settings.HardeningModulus = m_HardeningModulus;
                settings.NeckingStrain = m_NeckingStrain;
                settings.UltimateStrain = m_UltimateStrain;
            }
            if (m_EnergyAbsorber) settings.UseEnergyAbsorber(m_AbsorberForce, m_AbsorberDeployment);
            else
            {
                settings.EnergyAbsorber = false;
                settings.AbsorberForce = m_AbsorberForce;
                settings.AbsorberDeployment = m_AbsorberDeployment;
            }
        }

        /// <summary>How far the rope may reach beyond its rest length (m): the ultimate strain (plastic) and the absorber's deployment.</summary>
        float MaterialReach => (m_MaterialModel == MaterialModel.ElasticPlastic ? m_RestLength * m_UltimateStrain : 0f) + (m_EnergyAbsorber ? m_AbsorberDeployment : 0f);
    }
}
