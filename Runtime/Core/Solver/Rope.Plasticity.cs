using System;

namespace HookeRope.Solver
{
    /// <summary>
    /// The material law's state on the rope (issue 15): the plastic rest lengths, the plastic work, the neck and the energy
    /// absorber. Present only with <see cref="MaterialModel.ElasticPlastic"/> or <see cref="RopeSettings.EnergyAbsorber"/>;
    /// an elastic rope without an absorber has none and pays nothing.
    /// </summary>
    public sealed partial class Rope
    {
        private int requestedNeck = -1;

        /// <summary>Creates, re-reads or drops the plastic state after the settings changed (switching both off forgets the permanent set).</summary>
        private void ApplyPlasticity()
        {
            if (!settings.HasPlasticity)
            {
                chain.Plasticity = null;
                return;
            }
            if (chain.Plasticity == null) chain.Plasticity = new SegmentPlasticity(chain.SegmentCount);
            chain.Plasticity.Configure(settings, chain, requestedNeck);
        }

        /// <summary>
        /// Plastic work in joules since the plastic state was created: ∫T dL_p over the segments, the energy the permanent
        /// set, the neck and the energy absorber took out of the motion (0 for an elastic rope). Without damping,
        /// <see cref="TotalEnergy"/> + PlasticWork does not grow.
        /// </summary>
        public double PlasticWork => chain.Plasticity?.PlasticWork ?? 0.0;

        /// <summary>Permanent set in metres: Σ (L_p − L) over the intact segments, the absorber's deployment included (0 for an elastic rope).</summary>
        public double PlasticElongation => chain.Plasticity?.PlasticElongation(chain.Broken) ?? 0.0;

        /// <summary>How far the energy absorber has deployed, in metres (0 without one).</summary>
        public double AbsorberDeployment => chain.Plasticity?.Deployment ?? 0.0;

        /// <summary>The segment that holds the energy absorber (the last one), or −1 without one.</summary>
        public int AbsorberSegment => chain.Plasticity?.AbsorberSegment ?? -1;

        /// <summary>
        /// The segment that necks and softens with the elastic–plastic material (−1 for an elastic rope): the radius model's
        /// defect segment when the rope belongs to a <see cref="RopeSimulation"/> with a radius model, else the middle one.
        /// </summary>
        public int NeckSegment => chain.Plasticity?.NeckSegment ?? -1;

        /// <summary>Plastic rest length L_p of a segment in metres: its rest length plus its permanent set (the rest length for an elastic rope).</summary>
        public double GetPlasticRestLength(int segment)
        {
            CheckSegment(segment);
            return chain.CurrentRest(segment);
        }

        /// <summary>
        /// Softening progress of the neck in [0, 1] (0 at the neck onset, 1 at the ultimate strain), or −1 while no neck has
        /// formed or the rope has none: what the radius model draws the neck from.
        /// </summary>
        internal float NeckSoftening => chain.Plasticity?.NeckSoftening ?? -1f;

        /// <summary>True when the elastic–plastic material is on (with a finite E·A).</summary>
        internal bool IsRopePlastic => chain.Plasticity != null && chain.Plasticity.RopePlastic;

        /// <summary>
        /// Puts the neck at <paramref name="segment"/> (−1: the middle one); ignored once the neck has formed. The radius model's
        /// defect, set by <see cref="RopeSimulation"/>.
        /// </summary>
        internal void SetNeckSegment(int segment)
        {
            if (segment < -1 || segment >= chain.SegmentCount)
                throw new ArgumentOutOfRangeException(nameof(segment), segment, "segment must be -1 (the middle one) or in [0, " + (chain.SegmentCount - 1) + "]");
            requestedNeck = segment;
            chain.Plasticity?.SetNeck(segment);
        }
    }
}
