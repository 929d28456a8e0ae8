using System;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope
{
    /// <summary>
    /// Couples a core <see cref="Rope"/> with the core <see cref="RadiusModel"/> once per physics step: the model
    /// reads the current segment lengths and broken flags, its particle radii become the rope's collision radii,
    /// and when it asks for a break the rope is broken at the model's defect segment. Allocation-free per step.
    /// </summary>
    internal sealed class RopeRadiusBinding
    {
        readonly RadiusSettings _settings = new RadiusSettings();
        RadiusModel _model;
        bool[] _broken = Array.Empty<bool>();

        /// <summary>The model, or null when every radius feature is off.</summary>
        public RadiusModel Model => _model;

        /// <summary>The settings the model reads (changes apply at its next update).</summary>
        public RadiusSettings Settings => _settings;

        /// <summary>Creates the model for <paramref name="rope"/> with rest radius <paramref name="restRadius"/> (m), or drops it when <paramref name="active"/> is false.</summary>
        public void Build(Rope rope, float restRadius, bool active)
        {
            if (!active)
            {
                _model = null;
                return;
            }
            _model = new RadiusModel(_settings, restRadius, rope.RestLengths);
            if (_broken.Length != rope.SegmentCount) _broken = new bool[rope.SegmentCount];
            else Array.Clear(_broken, 0, _broken.Length);
        }

        /// <summary>Updates the radii after a rope step and breaks the rope at the defect when the model says so.</summary>
        public void Update(Rope rope)
        {
            if (_model == null) return;
            for (int s = 0; s < _broken.Length; s++) _broken[s] = rope.IsSegmentBroken(s);
            _model.Update(rope.SegmentLengths, _broken);
            var radii = _model.ParticleRadii;
            var target = rope.ParticleRadius;
            for (int i = 0; i < radii.Length && i < target.Length; i++) target[i] = radii[i];
            if (_model.ShouldBreak && !_model.IsBroken)
            {
                int segment = _model.DefectSegment;
                if (!rope.IsSegmentBroken(segment)) rope.BreakSegment(segment);
                _model.MarkBroken();
            }
        }

        /// <summary>The broken flags of the last update (empty before the first).</summary>
        public ReadOnlySpan<bool> Broken => _broken;
    }
}
