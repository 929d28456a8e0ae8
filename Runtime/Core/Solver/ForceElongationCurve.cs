using System;
using System.Collections.Generic;

namespace HookeRope.Solver
{
    /// <summary>
    /// The quasi-static force–elongation curve of a rope's material law (issue 15): the force F (N) against the total
    /// elongation e (m) of the whole rope pulled slowly at its ends, as the vertices of a piecewise-linear path (the law is
    /// piecewise linear, so the vertices are exact). All segments carry F; each stretches elastically by F·L_j/(E·A) and
    /// plastically by its permanent set. Rope segments (elastic–plastic) harden together from the yield force
    /// E·A·ε_y with slope H per unit plastic strain up to the neck onset F_n; then the neck segment (one segment, L/n)
    /// softens to zero force at the ultimate strain while the others unload elastically, keeping their set: the curve
    /// falls to the break. The energy absorber (the last segment) deploys at its plateau force by its deployment length,
    /// after which the webbing's elasticity takes over. The inspector's preview and the lab's plot draw it; the solver's
    /// slow pull follows it (tested).
    /// </summary>
    public sealed class ForceElongationCurve
    {
        private readonly List<double> elongation = new List<double>();
        private readonly List<double> force = new List<double>();

        private ForceElongationCurve()
        {
        }

        /// <summary>Number of vertices.</summary>
        public int Count => force.Count;

        /// <summary>Total elongation of the rope at each vertex, in metres (non-decreasing).</summary>
        public IReadOnlyList<double> Elongation => elongation;

        /// <summary>Force at each vertex, in newtons.</summary>
        public IReadOnlyList<double> Force => force;

        /// <summary>Elongation in metres at which the rope breaks (the neck's force reaches zero), or NaN when the curve has an open elastic end.</summary>
        public double BreakElongation { get; private set; } = double.NaN;

        /// <summary>Largest force on the curve in newtons (the neck onset for the elastic–plastic material).</summary>
        public double PeakForce
        {
            get
            {
                double peak = 0.0;
                foreach (double f in force) peak = Math.Max(peak, f);
                return peak;
            }
        }

        /// <summary>
        /// The curve of <paramref name="settings"/> (its rest length, segment count, E·A and material law). An elastic end
        /// (elastic material, or the webbing after the absorber) runs to the total strain <paramref name="endStrain"/>
        /// (dimensionless, &gt; 0; e.g. the break strain of the radius model), or a quarter beyond the last vertex when that is
        /// already past it; an inextensible end rises to 1.5 times the largest force.
        /// </summary>
        public static ForceElongationCurve Of(RopeSettings settings, double endStrain)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (!(endStrain > 0.0) || double.IsInfinity(endStrain))
                throw new ArgumentOutOfRangeException(nameof(endStrain), endStrain, "endStrain must be finite and in (0, +inf).");
            var curve = new ForceElongationCurve();
            curve.Build(settings, endStrain);
            return curve;
        }

        /// <summary>Force (N) on the loading path at elongation <paramref name="at"/> (m), linear between vertices; 0 past the break, the last force past an open end.</summary>
        public double ForceAt(double at)
        {
            if (at <= elongation[0]) return force[0];
            for (int i = 1; i < Count; i++)
            {
                if (at > elongation[i]) continue;
                double span = elongation[i] - elongation[i - 1];
                return span > 0.0 ? force[i - 1] + (force[i] - force[i - 1]) * (at - elongation[i - 1]) / span : force[i];
            }
            return double.IsNaN(BreakElongation) ? force[Count - 1] : 0.0;
        }

        private void Build(RopeSettings s, double endStrain)
        {
            double length = s.RestLength, ea = s.AxialStiffness;
            int n = s.SegmentCount;
            double segment = length / n;
            bool absorber = s.EnergyAbsorber;
            bool plastic = s.MaterialModel == MaterialModel.ElasticPlastic && double.IsFinite(ea);
            bool neck = plastic && !(absorber && n / 2 == n - 1);    // the neck (the middle segment) is never the absorber's
            double neckLength = neck ? segment : 0.0;
            double regularLength = length - (absorber ? segment : 0.0) - neckLength;
            double flex = double.IsFinite(ea) ? length / ea : 0.0;   // elastic elongation per newton of the whole rope, m/N
            double yield = plastic ? ea * s.YieldStrain : double.PositiveInfinity;
            double hardening = s.HardeningModulus;
            double onsetStrain = plastic ? (s.NeckingStrain - (double)s.YieldStrain) / (1.0 + hardening / ea) : 0.0;
            double onsetForce = plastic ? yield + hardening * onsetStrain : double.PositiveInfinity;
            double plateau = absorber ? s.AbsorberForce : double.PositiveInfinity;
            double p = 0.0, pn = 0.0, d = 0.0;   // plastic strain of the rope segments and of the neck, absorber deployment (m)
            void Add(double f)
            {
                force.Add(f);
                elongation.Add(f * flex + p * regularLength + pn * neckLength + d);
            }
            void Deploy(double atStrain)
            {
                p = pn = atStrain;
                Add(plateau);
                d = s.AbsorberDeployment;
                Add(plateau);
                absorber = false;
            }
            Add(0.0);
            if (!plastic)
            {
                if (absorber) Deploy(0.0);
                OpenEnd(endStrain * length, flex, 0.0);
                return;
            }
            if (absorber && plateau <= yield) Deploy(0.0);
            Add(yield);
            if (absorber && plateau < onsetForce) Deploy((plateau - yield) / hardening);   // H > 0 here: the plateau lies above the yield
            p = pn = onsetStrain;
            Add(onsetForce);
            if (!neck)
            {
                // no neck (it would be the absorber's segment): the rope segments harden on
                OpenEnd(endStrain * length, flex, hardening > 0.0 ? regularLength / hardening : double.PositiveInfinity);
                return;
            }
            pn = s.UltimateStrain;
            Add(0.0);
            BreakElongation = elongation[Count - 1];
        }

        /// <summary>
        /// The open end: from the last vertex to the elongation <paramref name="end"/> (m; at least a quarter beyond the last
        /// vertex) with the compliance <paramref name="flex"/> + <paramref name="plasticFlex"/> (m/N; +∞ plastic: a plateau);
        /// an inextensible end rises to 1.5 times the force at the same elongation.
        /// </summary>
        private void OpenEnd(double end, double flex, double plasticFlex)
        {
            double last = elongation[Count - 1], top = force[Count - 1];
            double total = flex + plasticFlex;
            if (total > 0.0)
            {
                end = Math.Max(end, 1.25 * last);
                force.Add(double.IsPositiveInfinity(total) ? top : top + (end - last) / total);
                elongation.Add(end);
            }
            else
            {
                force.Add(Math.Max(1.5 * top, top + 1.0));
                elongation.Add(last);
            }
        }
    }
}
