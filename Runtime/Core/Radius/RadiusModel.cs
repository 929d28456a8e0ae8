using System;

namespace HookeRope.Radius
{
    /// <summary>
    /// Per-segment and per-ring radii of a rope from its rest and current segment lengths: Poisson thinning
    /// (eq. 16) from each segment's own stretch, smoothed to the particles; a neck at the defect (Paper or Zone
    /// mode); and the break decision at the defect segment. Allocation-free after construction.
    /// </summary>
    public sealed class RadiusModel
    {
        private readonly float[] segmentRadii;
        private readonly float[] baseParticleRadii;
        private readonly float[] particleRadii;
        private readonly float[] restArc;
        private readonly float[] currentArc;
        private readonly float[] segmentStretch;
        private readonly bool[] segmentBroken;
        private readonly float restRadius;
        private int defectSegment;
        private float defectT;
        private float defectArc;
        private float neckDepth;
        private float zoneWaistSquared = 1f;
        private float paperWaist;
        private float paperAxisSquared;
        private float paperCenter;
        private bool paperNecking;
        private float neckRadius;
        private float minRadius;
        private BreakReason breakReason;
        private bool broken;
        private bool materialNeck;
        private float materialSoftening = -1f;
        private float materialUltimateStrain = float.PositiveInfinity;

        /// <summary>
        /// Creates the model for a rope with rest radius <paramref name="restRadius"/> (m, finite, &gt; 0) and the
        /// given rest segment lengths (m, each finite and &gt; 0; at least one segment). Radii start at R.
        /// </summary>
        public RadiusModel(RadiusSettings settings, float restRadius, ReadOnlySpan<float> restLengths)
        {
            Settings = settings ?? throw new ArgumentNullException(nameof(settings));
            if (!float.IsFinite(restRadius) || !(restRadius > 0f))
                throw new ArgumentOutOfRangeException(nameof(restRadius), restRadius, "restRadius must be finite and in (0, +inf) m.");
            if (restLengths.Length < 1)
                throw new ArgumentException("restLengths must hold at least one segment length (1 … any).", nameof(restLengths));
            int n = restLengths.Length;
            this.restRadius = restRadius;
            segmentRadii = new float[n];
            segmentStretch = new float[n];
            segmentBroken = new bool[n];
            baseParticleRadii = new float[n + 1];
            particleRadii = new float[n + 1];
            restArc = new float[n + 1];
            currentArc = new float[n + 1];
            double sum = 0.0;
            for (int j = 0; j < n; j++)
            {
                float length = restLengths[j];
                if (!float.IsFinite(length) || !(length > 0f))
                    throw new ArgumentOutOfRangeException(nameof(restLengths), length, "every rest length must be finite and in (0, +inf) m.");
                sum += length;
                restArc[j + 1] = (float)sum;
                currentArc[j + 1] = (float)sum;
                segmentStretch[j] = 1f;
            }
            Array.Fill(segmentRadii, restRadius);
            Array.Fill(baseParticleRadii, restRadius);
            Array.Fill(particleRadii, restRadius);
            neckRadius = restRadius;
            minRadius = restRadius;
            LocateDefect();
        }

        /// <summary>The settings read at every update.</summary>
        public RadiusSettings Settings { get; }

        /// <summary>Rest radius R in metres.</summary>
        public float RestRadius => restRadius;

        /// <summary>Number of segments.</summary>
        public int SegmentCount => segmentRadii.Length;

        /// <summary>Total rest length in metres.</summary>
        public float RestLength => restArc[restArc.Length - 1];

        /// <summary>Poisson radius of each segment in metres (R when thinning is off or the segment is broken).</summary>
        public ReadOnlySpan<float> SegmentRadii => segmentRadii;

        /// <summary>Radius at each particle in metres, neck included (what colliders should use).</summary>
        public ReadOnlySpan<float> ParticleRadii => particleRadii;

        /// <summary>Index of the segment holding the defect (where the neck forms and the rope breaks).</summary>
        public int DefectSegment => defectSegment;

        /// <summary>Position of the defect inside <see cref="DefectSegment"/> as a fraction of its length, [0, 1].</summary>
        public float DefectFraction => defectT;

        /// <summary>Rest arc length from the first particle to the defect in metres.</summary>
        public float DefectRestArc => defectArc;

        /// <summary>Rest length of the neck zone in metres (Zone mode): NeckZoneDiameters·2R.</summary>
        public float NeckZoneRestLength => Settings.NeckZoneDiameters * 2f * restRadius;

        /// <summary>Radius at the defect in metres, neck included (the Poisson radius there when no neck has formed).</summary>
        public float NeckRadius => neckRadius;

        /// <summary>Smallest radius along the rope in metres (particles and the neck waist).</summary>
        public float MinRadius => minRadius;

        /// <summary>Neck depth in [0, 1]: Zone mode grows it continuously from 0 at onset; Paper mode is 0 or 1.</summary>
        public float NeckDepth => neckDepth;

        /// <summary>True once the neck has started to form.</summary>
        public bool IsNecking => neckDepth > 0f;

        /// <summary>The break decision of the last update (None until a criterion is met; reset by <see cref="MarkBroken"/>).</summary>
        public BreakReason BreakReason => breakReason;

        /// <summary>True when the last update decided that the rope breaks at <see cref="DefectSegment"/>.</summary>
        public bool ShouldBreak => breakReason != BreakReason.None;

        /// <summary>True after <see cref="MarkBroken"/>: the neck is frozen and no further break is asked for.</summary>
        public bool IsBroken => broken;

        /// <summary>True when any part is enabled; when false <see cref="Update"/> returns at once.</summary>
        public bool IsActive => Settings.AnyEnabled;

        /// <summary>
        /// Incremented by every <see cref="Update"/> or <see cref="MarkBroken"/> that changed what <see cref="RadiusAt"/>
        /// returns (compared bitwise): the mesh skips its ring-radius work while it stays the same.
        /// </summary>
        internal int RadiiVersion { get; private set; }

        /// <summary>
        /// Recomputes radii from the current segment lengths (m) and the broken flags (null/empty = none broken),
        /// then the break decision. Spans must hold <see cref="SegmentCount"/> values. Allocation-free; does
        /// nothing when every part is off. Non-finite lengths count as unstretched.
        /// </summary>
        public void Update(ReadOnlySpan<float> currentLengths, ReadOnlySpan<bool> brokenSegments)
        {
            if (!Settings.AnyEnabled) return;
            int n = segmentRadii.Length;
            if (currentLengths.Length != n)
                throw new ArgumentException("currentLengths must hold SegmentCount = " + n + " values.", nameof(currentLengths));
            bool hasBroken = brokenSegments.Length > 0;
            if (hasBroken && brokenSegments.Length != n)
                throw new ArgumentException("brokenSegments must be empty or hold SegmentCount = " + n + " flags.", nameof(brokenSegments));
            RadiusSettings s = Settings;
            double nu = s.PoissonRatio;
            bool slack = s.SlackKeepsRestRadius;
            var before = new ProfileKey(this);
            bool profileMoved = false;
            bool paperProfile = s.Necking && s.NeckMode == NeckMode.Paper; // the only profile that reads the current arc
            double arc = 0.0;
            for (int j = 0; j < n; j++)
            {
                float rest = restArc[j + 1] - restArc[j];
                float current = currentLengths[j];
                bool isBroken = hasBroken && brokenSegments[j];
                segmentBroken[j] = isBroken;
                if (isBroken || !float.IsFinite(current)) current = rest;
                segmentStretch[j] = current / rest;
                arc += current;
                profileMoved |= paperProfile && currentArc[j + 1] != (float)arc;
                currentArc[j + 1] = (float)arc;
                segmentRadii[j] = s.PoissonThinning && !isBroken
                    ? (float)(restRadius * PoissonRadius.Ratio(rest, current, nu, slack))
                    : restRadius;
            }
            profileMoved |= SmoothToParticles(hasBroken ? brokenSegments : default);
            LocateDefect();
            UpdateNeck();
            if (profileMoved || !before.Equals(new ProfileKey(this))) RadiiVersion++;
            float smallest = float.PositiveInfinity;
            if (neckDepth <= 0f && n > 0)
            {
                // no neck: RadiusAt's Poisson interpolation at each particle (t = 0; t = 1 on the last segment, which its
                // clamp keeps), the range check and the neck test hoisted out (the same operations, so the same bits)
                ReadOnlySpan<float> particle = baseParticleRadii;
                ReadOnlySpan<bool> parted = segmentBroken;
                Span<float> radii = particleRadii;
                for (int i = 0; i <= n; i++)
                {
                    int segment = i < n ? i : n - 1;
                    float t = i < n ? 0f : 1f;
                    float r = parted[segment]
                        ? particle[t <= 0.5f ? segment : segment + 1]
                        : particle[segment] + (particle[segment + 1] - particle[segment]) * t;
                    radii[i] = r;
                    if (r < smallest) smallest = r;
                }
            }
            else
            {
                for (int i = 0; i <= n; i++)
                {
                    float r = RadiusAt(i < n ? i : n - 1, i < n ? 0f : 1f);
                    particleRadii[i] = r;
                    if (r < smallest) smallest = r;
                }
            }
            neckRadius = RadiusAt(defectSegment, defectT);
            if (s.Necking && s.NeckMode == NeckMode.Paper && paperNecking) neckRadius = Math.Min(neckRadius, paperWaist);
            minRadius = Math.Min(smallest, neckRadius);
            DecideBreak();
        }

        /// <summary>
        /// Radius in metres at fraction <paramref name="t"/> ∈ [0, 1] (clamped) of segment <paramref name="segment"/>
        /// (0 … SegmentCount − 1): the particle radii interpolated linearly, times the neck profile where it applies. A
        /// broken segment parted at its middle: t ≤ ½ takes the radius of particle <paramref name="segment"/>, t &gt; ½ that
        /// of particle segment + 1 (each dangling half keeps the radius of the end it hangs from).
        /// </summary>
        public float RadiusAt(int segment, float t)
        {
            if ((uint)segment >= (uint)segmentRadii.Length)
                throw new ArgumentOutOfRangeException(nameof(segment), segment, "segment must be in [0, SegmentCount - 1].");
            if (t < 0f) t = 0f; else if (t > 1f) t = 1f;
            // a broken segment parted at its middle: each half keeps the radius of the end it hangs from
            float baseRadius = segmentBroken[segment]
                ? baseParticleRadii[t <= 0.5f ? segment : segment + 1]
                : baseParticleRadii[segment] + (baseParticleRadii[segment + 1] - baseParticleRadii[segment]) * t;
            return WithNeck(segment, t, baseRadius);
        }

        /// <summary>
        /// Radius in metres of the cut end of broken segment <paramref name="segment"/> on the side of particle
        /// <paramref name="segment"/> (<paramref name="upperSide"/> false) or particle segment + 1 (true): that end's own
        /// radius times the frozen neck at the middle of the segment, where the rope parted. Both ends share the neck, so
        /// they differ only by the Poisson radius of the pieces they end. For an intact segment: the radius at its middle.
        /// </summary>
        public float BrokenEndRadius(int segment, bool upperSide)
        {
            if ((uint)segment >= (uint)segmentRadii.Length)
                throw new ArgumentOutOfRangeException(nameof(segment), segment, "segment must be in [0, SegmentCount - 1].");
            if (!segmentBroken[segment]) return RadiusAt(segment, 0.5f);
            return WithNeck(segment, 0.5f, baseParticleRadii[upperSide ? segment + 1 : segment]);
        }

        /// <summary>The radius (m) at fraction t of a segment whose Poisson radius there is <paramref name="baseRadius"/> (m), neck applied.</summary>
        private float WithNeck(int segment, float t, float baseRadius)
        {
            if (neckDepth <= 0f) return baseRadius;
            if (Settings.NeckMode == NeckMode.Zone)
            {
                float s = restArc[segment] + (restArc[segment + 1] - restArc[segment]) * t;
                return baseRadius * NeckProfile.Ratio((s - defectArc) / NeckZoneRestLength, zoneWaistSquared);
            }
            if (Settings.NeckMode == NeckMode.Paper && paperNecking)
            {
                float c = currentArc[segment] + (currentArc[segment + 1] - currentArc[segment]) * t;
                float y = c - paperCenter;
                return paperAxisSquared > 0f ? paperWaist * MathF.Sqrt(1f + y * y / paperAxisSquared) : paperWaist;
            }
            return baseRadius;
        }

        /// <summary>
        /// Fills <paramref name="radii"/> (m) with the radius at each ring station given by parallel spans of
        /// segment indices and fractions (e.g. a <see cref="HookeRope.Geometry.RingLayout"/>). Allocation-free.
        /// </summary>
        public void FillRadiiAt(ReadOnlySpan<int> ringSegments, ReadOnlySpan<float> ringFractions, Span<float> radii)
        {
            if (ringSegments.Length != ringFractions.Length || radii.Length < ringSegments.Length)
                throw new ArgumentException("radii must hold at least as many values as ringSegments and ringFractions (which must match).", nameof(radii));
            if (neckDepth > 0f)
            {
                for (int k = 0; k < ringSegments.Length; k++) radii[k] = RadiusAt(ringSegments[k], ringFractions[k]);
                return;
            }
            // no neck: RadiusAt's Poisson interpolation only, its checks and the neck test hoisted out of the loop (the
            // same operations on the same values, so the same bits)
            ReadOnlySpan<float> particle = baseParticleRadii;
            ReadOnlySpan<bool> broken = segmentBroken;
            int segments = segmentRadii.Length;
            radii = radii.Slice(0, ringSegments.Length);
            ringFractions = ringFractions.Slice(0, ringSegments.Length);
            // a layout's rings of one segment are consecutive: the segment's ends once per run
            int current = -1;
            float r0 = 0f, r1 = 0f, rise = 0f;
            bool parted = false;
            for (int k = 0; k < radii.Length; k++)
            {
                int segment = ringSegments[k];
                if (segment != current)
                {
                    if ((uint)segment >= (uint)segments)
                        throw new ArgumentOutOfRangeException(nameof(ringSegments), segment, "ring segments must be in [0, SegmentCount - 1].");
                    current = segment;
                    r0 = particle[segment];
                    r1 = particle[segment + 1];
                    rise = r1 - r0;
                    parted = broken[segment];
                }
                float t = ringFractions[k];
                if (t < 0f) t = 0f; else if (t > 1f) t = 1f;
                radii[k] = parted ? (t <= 0.5f ? r0 : r1) : r0 + rise * t;
            }
        }

        /// <summary>True when the neck follows the rope's elastic–plastic material (<see cref="FollowMaterial"/>) instead of the radius threshold.</summary>
        public bool FollowsMaterial => materialNeck;

        /// <summary>
        /// The elastic–plastic material drives the neck (issue 15; call before <see cref="Update"/>): with
        /// <paramref name="plastic"/> the neck forms when the material's plastic strain localises at the defect, i.e. when
        /// <paramref name="softening"/> (the neck segment's softening progress, 0 at onset … 1 at the ultimate strain; &lt; 0
        /// before onset) reaches 0, instead of at <see cref="RadiusSettings.NeckRadiusFraction"/>. In Zone mode the waist's
        /// area follows the force the neck still carries: ρ² = 1 − s (the neck's true stress stays at its onset value while the
        /// engineering stress falls). The break is at <paramref name="ultimateStrain"/> (the defect segment's strain) instead of
        /// <see cref="RadiusSettings.BreakStrain"/>, or earlier when the waist falls below
        /// <see cref="RadiusSettings.BreakRadiusFraction"/>·R. <paramref name="plastic"/> false restores the elastic-rope rules.
        /// </summary>
        public void FollowMaterial(bool plastic, float softening, float ultimateStrain)
        {
            materialNeck = plastic;
            materialSoftening = plastic ? softening : -1f;
            materialUltimateStrain = plastic ? ultimateStrain : float.PositiveInfinity;
        }

        /// <summary>
        /// Tells the model that the host broke the rope: the neck is frozen at its present depth (Zone) or
        /// dropped (Paper), the break decision resets to None and no further break is asked for.
        /// </summary>
        public void MarkBroken()
        {
            RadiiVersion++;
            broken = true;
            breakReason = BreakReason.None;
            paperNecking = false;
            if (Settings.NeckMode == NeckMode.Paper) neckDepth = 0f;
        }

        /// <summary>Particle radii from the segment radii; returns true when one changed (bitwise).</summary>
        private bool SmoothToParticles(ReadOnlySpan<bool> brokenSegments)
        {
            int n = segmentRadii.Length;
            bool any = brokenSegments.Length > 0;
            bool moved = false;
            for (int i = 0; i <= n; i++)
            {
                bool left = i > 0 && !(any && brokenSegments[i - 1]);
                bool right = i < n && !(any && brokenSegments[i]);
                float r;
                if (left && right) r = 0.5f * (segmentRadii[i - 1] + segmentRadii[i]);
                else if (left) r = segmentRadii[i - 1];
                else if (right) r = segmentRadii[i];
                else r = restRadius;
                moved |= BitConverter.SingleToInt32Bits(baseParticleRadii[i]) != BitConverter.SingleToInt32Bits(r);
                baseParticleRadii[i] = r;
            }
            return moved;
        }

        /// <summary>The scalars <see cref="RadiusAt"/> reads besides the particle radii and arcs.</summary>
        private readonly struct ProfileKey : IEquatable<ProfileKey>
        {
            private readonly int defectSegment;
            private readonly float defectArc, neckDepth, zoneWaistSquared, paperWaist, paperAxisSquared, paperCenter;
            private readonly bool paperNecking;

            public ProfileKey(RadiusModel model)
            {
                defectSegment = model.defectSegment;
                defectArc = model.defectArc;
                neckDepth = model.neckDepth;
                zoneWaistSquared = model.zoneWaistSquared;
                paperWaist = model.paperWaist;
                paperAxisSquared = model.paperAxisSquared;
                paperCenter = model.paperCenter;
                paperNecking = model.paperNecking;
            }

            public bool Equals(ProfileKey o) =>
                defectSegment == o.defectSegment && paperNecking == o.paperNecking && Bits(defectArc) == Bits(o.defectArc)
                && Bits(neckDepth) == Bits(o.neckDepth) && Bits(zoneWaistSquared) == Bits(o.zoneWaistSquared)
                && Bits(paperWaist) == Bits(o.paperWaist) && Bits(paperAxisSquared) == Bits(o.paperAxisSquared)
                && Bits(paperCenter) == Bits(o.paperCenter);

            public override bool Equals(object obj) => obj is ProfileKey other && Equals(other);

            public override int GetHashCode() => defectSegment;

            private static int Bits(float value) => BitConverter.SingleToInt32Bits(value);
        }

        private void LocateDefect()
        {
            int n = segmentRadii.Length;
            float position = Settings.Necking && Settings.NeckMode == NeckMode.Paper ? 0.5f : Settings.DefectPosition;
            float target = position * restArc[n];
            int j = 0;
            while (j < n - 1 && restArc[j + 1] <= target) j++;
            defectSegment = j;
            if (Settings.NeckMode == NeckMode.Zone)
            {
                // The waist sits in the middle of the segment that breaks: both halves keep the same half-neck.
                defectT = 0.5f;
                defectArc = 0.5f * (restArc[j] + restArc[j + 1]);
                return;
            }
            float length = restArc[j + 1] - restArc[j];
            float t = (target - restArc[j]) / length;
            defectT = t < 0f ? 0f : (t > 1f ? 1f : t);
            defectArc = target;
        }

        private void UpdateNeck()
        {
            RadiusSettings s = Settings;
            if (!s.Necking) { neckDepth = 0f; paperNecking = false; return; }
            if (broken) return;
            double strain = segmentStretch[defectSegment] - 1.0;
            double onset = PoissonRadius.StrainAtRatio(s.NeckRadiusFraction, s.PoissonRatio);
            float rMin = s.NeckRadiusFraction * restRadius;
            if (materialNeck)
            {
                // the plastic material: onset where its strain localises, the waist's area following the neck's force
                if (materialSoftening < 0f) { neckDepth = 0f; paperNecking = false; zoneWaistSquared = 1f; return; }
                if (s.NeckMode == NeckMode.Zone)
                {
                    neckDepth = materialSoftening;
                    zoneWaistSquared = 1f - materialSoftening;
                    paperNecking = false;
                    return;
                }
                onset = double.NegativeInfinity;
            }
            if (s.NeckMode == NeckMode.Zone)
            {
                double depth = (strain - onset) / s.NeckGrowthStrain;
                neckDepth = depth > 0.0 ? (depth < 1.0 ? (float)depth : 1f) : 0f;
                float zoneLength = NeckZoneRestLength * segmentStretch[defectSegment];
                float zoneWaistRatio = NeckHyperbola.WaistRadius(zoneLength, rMin) / rMin;
                float waist = 1f - neckDepth * (1f - zoneWaistRatio);
                zoneWaistSquared = waist * waist;
                paperNecking = false;
                return;
            }
            paperNecking = strain >= onset;
            neckDepth = paperNecking ? 1f : 0f;
            if (!paperNecking) return;
            float length = currentArc[currentArc.Length - 1];
            paperWaist = NeckHyperbola.WaistRadius(length, rMin);
            paperAxisSquared = NeckHyperbola.AxisSquared(length, rMin);
            paperCenter = 0.5f * length;
        }

        /// <summary>
        /// The one fracture criterion: with <see cref="RadiusSettings.Fracture"/> on, the defect segment breaks when
        /// its strain reaches <see cref="RadiusSettings.BreakStrain"/> (the material's ultimate strain when the neck
        /// <see cref="FollowsMaterial"/>), or, only with <see cref="RadiusSettings.Necking"/>
        /// on, when the neck radius falls below <see cref="RadiusSettings.BreakRadiusFraction"/>·R.
        /// </summary>
        private void DecideBreak()
        {
            RadiusSettings s = Settings;
            breakReason = BreakReason.None;
            if (!s.Fracture || broken) return;
            float breakStrain = materialNeck ? materialUltimateStrain : s.BreakStrain;
            if (segmentStretch[defectSegment] - 1f >= breakStrain) breakReason = BreakReason.Strain;
            else if (s.Necking && neckRadius < s.BreakRadiusFraction * restRadius) breakReason = BreakReason.NeckRadius;
        }
    }
}
