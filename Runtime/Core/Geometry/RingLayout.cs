using System;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Where the rings of a tube sit along the rope: segment j holds <c>RingsIn(j)</c> rings at fractions
    /// t = i/RingsIn(j), i = 0 … RingsIn(j) − 1 (or given ones), and one last ring sits at the last particle (t = 1 of
    /// the last segment). Ring k at particle j is <c>FirstRing(j)</c>. The layouts made by the constructors and factories
    /// are fixed; the adaptive rings (<see cref="AdaptiveRings"/>) rewrite theirs in place before a build
    /// (<see cref="Begin"/> … <see cref="End"/>), and <see cref="Version"/> counts the rewrites that moved a ring. Storage
    /// grows only when a layout holds more rings than any before it.
    /// </summary>
    internal sealed class RingLayout
    {
        /// <summary>Largest number of rings in one segment.</summary>
        public const int MaxRingsPerSegment = 1024;

        private readonly int[] firstRing;
        private int[] ringSegment;
        private float[] ringFraction;
        private int ringCount;
        private int writeCursor;
        private int writeSegment;
        private bool writeChanged;

        /// <summary>Uniform layout: <paramref name="ringsPerSegment"/> (1 … 1024) rings in each of <paramref name="segmentCount"/> (≥ 1) segments.</summary>
        public RingLayout(int segmentCount, int ringsPerSegment)
            : this(Uniform(segmentCount, ringsPerSegment))
        {
        }

        /// <summary>Layout with a ring count (1 … 1024) per segment, rings evenly spaced in each segment.</summary>
        public RingLayout(ReadOnlySpan<int> ringsPerSegment)
            : this(ringsPerSegment, ReadOnlySpan<float>.Empty)
        {
        }

        /// <summary>
        /// Layout with a ring count (1 … 1024) per segment and, when <paramref name="fractions"/> is not empty, the
        /// fraction of every ring in its segment (Σ counts values, segment by segment; each segment's first 0, then
        /// strictly increasing below 1). Empty fractions space the rings evenly.
        /// </summary>
        public RingLayout(ReadOnlySpan<int> ringsPerSegment, ReadOnlySpan<float> fractions)
        {
            int n = ringsPerSegment.Length;
            if (n < 1) throw new ArgumentException("ringsPerSegment must hold at least one segment (1 … any).", nameof(ringsPerSegment));
            firstRing = new int[n + 1];
            int total = 0;
            for (int j = 0; j < n; j++)
            {
                int m = ringsPerSegment[j];
                if (m < 1 || m > MaxRingsPerSegment)
                    throw new ArgumentOutOfRangeException(nameof(ringsPerSegment), m, "every ring count must be in [1, 1024].");
                firstRing[j] = total;
                total += m;
            }
            firstRing[n] = total;
            if (fractions.Length != 0 && fractions.Length != total)
                throw new ArgumentException("fractions must be empty or hold one value per ring (" + total + ").", nameof(fractions));
            ringSegment = new int[total + 1];
            ringFraction = new float[total + 1];
            for (int j = 0; j < n; j++)
            {
                int m = ringsPerSegment[j];
                for (int i = 0; i < m; i++)
                {
                    int k = firstRing[j] + i;
                    float t = fractions.Length == 0 ? (float)i / m : fractions[k];
                    bool valid = i == 0 ? t == 0f : t > ringFraction[k - 1] && t < 1f;
                    if (!valid)
                        throw new ArgumentOutOfRangeException(nameof(fractions), t, "each segment's fractions must start at 0 and increase strictly in [0, 1).");
                    ringSegment[k] = j;
                    ringFraction[k] = t;
                }
            }
            ringSegment[total] = n - 1;
            ringFraction[total] = 1f;
            ringCount = total + 1;
        }

        /// <summary>Number of segments.</summary>
        public int SegmentCount => firstRing.Length - 1;

        /// <summary>Number of rings of the intact rope (Σ RingsIn + 1).</summary>
        public int RingCount => ringCount;

        /// <summary>Incremented by every rewrite (<see cref="End"/>) that moved, added or removed a ring.</summary>
        public int Version { get; private set; }

        /// <summary>Index of the ring at particle <paramref name="particle"/> (0 … SegmentCount).</summary>
        public int FirstRing(int particle) => firstRing[particle];

        /// <summary>The first ring at each particle (<see cref="FirstRing"/> of particles 0 … SegmentCount).</summary>
        internal ReadOnlySpan<int> FirstRings => firstRing;

        /// <summary>Rings in segment <paramref name="segment"/>.</summary>
        public int RingsIn(int segment) => firstRing[segment + 1] - firstRing[segment];

        /// <summary>Segment of each ring.</summary>
        public ReadOnlySpan<int> RingSegments => new ReadOnlySpan<int>(ringSegment, 0, ringCount);

        /// <summary>Fraction t ∈ [0, 1] of each ring inside its segment.</summary>
        public ReadOnlySpan<float> RingFractions => new ReadOnlySpan<float>(ringFraction, 0, ringCount);

        /// <summary>
        /// A layout of one ring per segment for <paramref name="segmentCount"/> (≥ 1) segments with room for
        /// <paramref name="capacity"/> rings, to be rewritten in place (<see cref="Begin"/>) without allocating.
        /// </summary>
        internal static RingLayout Rewritable(int segmentCount, int capacity)
        {
            var layout = new RingLayout(segmentCount, 1);
            if (capacity > layout.ringSegment.Length)
            {
                Array.Resize(ref layout.ringSegment, capacity);
                Array.Resize(ref layout.ringFraction, capacity);
            }
            return layout;
        }

        /// <summary>
        /// Starts a rewrite in place: add every segment's rings in segment order with <see cref="Add"/> or
        /// <see cref="AddUniformRuns"/> (each segment at least one, starting at t = 0, fractions increasing below 1; the
        /// callers guarantee it), then <see cref="End"/>.
        /// </summary>
        internal void Begin()
        {
            writeCursor = 0;
            writeSegment = -1;
            writeChanged = false;
        }

        /// <summary>Appends a ring of segment <paramref name="segment"/> at fraction <paramref name="t"/> ∈ [0, 1).</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal void Add(int segment, float t)
        {
            while (writeSegment < segment)
            {
                writeSegment++;
                firstRing[writeSegment] = writeCursor;
            }
            Put(writeCursor++, segment, t);
        }

        /// <summary>
        /// Appends, for segments <paramref name="segment"/>, <paramref name="segment"/> + 1, … in order, counts[s] (≥ 1)
        /// evenly spaced rings of segment <paramref name="segment"/> + s, t = i/count as the uniform layouts: Add's segment
        /// step, then Put's compare-and-store per ring, with the capacity checked and the ring arrays sliced once for the
        /// whole run of segments.
        /// </summary>
        internal void AddUniformRuns(int segment, ReadOnlySpan<int> counts)
        {
            if (counts.Length == 0) return;
            while (writeSegment < segment)
            {
                writeSegment++;
                firstRing[writeSegment] = writeCursor;
            }
            int start = writeCursor, total = 0;
            for (int s = 0; s < counts.Length; s++) total += counts[s];
            if (start + total > ringSegment.Length)
            {
                int size = Math.Max(start + total, 2 * ringSegment.Length);
                Array.Resize(ref ringSegment, size);
                Array.Resize(ref ringFraction, size);
            }
            Span<int> segments = new Span<int>(ringSegment, start, total);
            Span<float> fractions = new Span<float>(ringFraction, start, total);
            // the first ring of each segment after the first (Add's step: one segment at a time)
            Span<int> firsts = new Span<int>(firstRing, segment, counts.Length);
            int kept = ringCount - start; // rings below the last layout's count compare with it
            bool changed = false;
            int k = 0;
            for (int s = 0; s < counts.Length; s++)
            {
                int count = counts[s], here = segment + s;
                if (s > 0) firsts[s] = start + k;
                Span<int> ringSegments = segments.Slice(k, count);
                Span<float> ringFractions = fractions.Slice(k, count).Slice(0, ringSegments.Length);
                int keptHere = kept - k;
                // t = (float)i / count, with i and count as floats formed once (i counted up in floats: exact below 2²⁴)
                float divisor = count, place = 0f;
                for (int i = 0; i < ringSegments.Length; i++, place += 1f)
                {
                    float t = place / divisor;
                    if (i < keptHere && ringSegments[i] == here && ringFractions[i] == t) continue;
                    changed = true;
                    ringSegments[i] = here;
                    ringFractions[i] = t;
                }
                k += count;
            }
            writeSegment = segment + counts.Length - 1;
            writeChanged |= changed;
            writeCursor = start + total;
        }

        /// <summary>Ends a rewrite with the last ring on the last particle; <see cref="Version"/> moves when a ring did.</summary>
        internal void End()
        {
            int n = SegmentCount;
            while (writeSegment < n)
            {
                writeSegment++;
                firstRing[writeSegment] = writeCursor;
            }
            Put(writeCursor++, n - 1, 1f);
            if (writeCursor != ringCount) writeChanged = true;
            ringCount = writeCursor;
            if (writeChanged) Version++;
        }

        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private void Put(int k, int segment, float t)
        {
            if (k >= ringSegment.Length)
            {
                int size = Math.Max(k + 1, 2 * ringSegment.Length);
                Array.Resize(ref ringSegment, size);
                Array.Resize(ref ringFraction, size);
            }
            if (k < ringCount && ringSegment[k] == segment && ringFraction[k] == t) return;
            writeChanged = true;
            ringSegment[k] = segment;
            ringFraction[k] = t;
        }

        /// <summary>
        /// A layout with <paramref name="ringsPerSegment"/> rings per segment, and more in the segments that overlap
        /// the rest-arc interval [<paramref name="zoneCenter"/> ± <paramref name="zoneLength"/>/2] (m), so that the
        /// zone holds about <paramref name="ringsInZone"/> rings (capped at 1024 per segment). For the neck zone.
        /// </summary>
        public static RingLayout Refined(ReadOnlySpan<float> restLengths, int ringsPerSegment, float zoneCenter, float zoneLength, int ringsInZone)
        {
            int n = restLengths.Length;
            int[] counts = Uniform(n, ringsPerSegment);
            if (zoneLength > 0f && ringsInZone > 0)
            {
                float start = zoneCenter - 0.5f * zoneLength;
                float end = zoneCenter + 0.5f * zoneLength;
                float arc = 0f;
                for (int j = 0; j < n; j++)
                {
                    float next = arc + restLengths[j];
                    if (next > start && arc < end)
                    {
                        double wanted = Math.Ceiling(ringsInZone * (double)restLengths[j] / zoneLength);
                        int m = wanted > MaxRingsPerSegment ? MaxRingsPerSegment : (int)wanted;
                        if (m > counts[j]) counts[j] = m;
                    }
                    arc = next;
                }
            }
            return new RingLayout(counts);
        }

        /// <summary>
        /// A layout with <paramref name="ringsPerSegment"/> rings per segment outside the neck zone
        /// [<paramref name="zoneCenter"/> ± <paramref name="zoneLength"/>/2] (rest arc, m) and, inside it, rings whose
        /// density follows the curvature of a deep neck profile (<see cref="HookeRope.Radius.NeckProfile"/>, waist
        /// ratio <see cref="ReferenceWaistRatio"/>, rope radius <paramref name="restRadius"/> in m): the profile's
        /// tangent turns by at most π/<paramref name="radialSegments"/> between rings, the angle between neighbouring
        /// vertices around the tube, plus <see cref="BaseRingsInZone"/> evenly spread rings. The waist is then as round
        /// along the rope as the rings are around it, from 8 to 32 radial segments.
        /// </summary>
        public static RingLayout Adapted(ReadOnlySpan<float> restLengths, int ringsPerSegment, float zoneCenter, float zoneLength,
            float restRadius, int radialSegments)
        {
            int n = restLengths.Length;
            int[] counts = Uniform(n, ringsPerSegment);
            if (!(zoneLength > 0f) || !(restRadius > 0f) || radialSegments < 3) return new RingLayout(counts);
            double[] stations = NeckStations(zoneCenter, zoneLength, restRadius, radialSegments);
            var all = new System.Collections.Generic.List<float>();
            double arc = 0.0;
            double start = stations[0], end = stations[stations.Length - 1];
            for (int j = 0; j < n; j++)
            {
                double length = restLengths[j], next = arc + length;
                int before = all.Count;
                all.Add(0f);
                int m = counts[j];
                int z = 0;
                while (z < stations.Length && stations[z] <= arc) z++;
                for (int i = 1; i < m || z < stations.Length && stations[z] < next; )
                {
                    double uniform = i < m ? arc + length * i / m : double.MaxValue;
                    if (i < m && uniform > start && uniform < end) { i++; continue; }
                    double station = z < stations.Length && stations[z] < next ? stations[z] : double.MaxValue;
                    double s = Math.Min(uniform, station);
                    if (s == uniform) i++; else z++;
                    float t = (float)((s - arc) / length);
                    if (t > all[all.Count - 1] + 1e-3f && t < 1f - 1e-3f && all.Count - before < MaxRingsPerSegment) all.Add(t);
                }
                counts[j] = all.Count - before;
                arc = next;
            }
            return new RingLayout(counts, all.ToArray());
        }

        /// <summary>Waist ratio ρ of the neck profile the adapted layout is made for (a neck close to breaking).</summary>
        public const float ReferenceWaistRatio = 0.2f;

        /// <summary>Evenly spread rings in the neck zone of an adapted layout, on top of the curvature-driven ones.</summary>
        public const int BaseRingsInZone = 12;

        /// <summary>Rest-arc stations (m) of the rings in the neck zone: equal steps of (x / BaseRingsInZone + turn / (π/radial)).</summary>
        private static double[] NeckStations(float zoneCenter, float zoneLength, float restRadius, int radialSegments)
        {
            const int samples = 512;
            double scale = 2.0 * restRadius / zoneLength; // d(r/R)/dx → dr/ds
            double angleStep = Math.PI / radialSegments;
            var monitor = new double[samples + 1];
            double previous = Math.Atan(scale * Radius.NeckProfile.Slope(-1.0, ReferenceWaistRatio));
            for (int i = 1; i <= samples; i++)
            {
                double x = -1.0 + 2.0 * i / samples;
                double angle = Math.Atan(scale * Radius.NeckProfile.Slope(x, ReferenceWaistRatio));
                monitor[i] = monitor[i - 1] + (double)BaseRingsInZone / samples + Math.Abs(angle - previous) / angleStep;
                previous = angle;
            }
            int count = 2 * (int)Math.Ceiling(0.5 * monitor[samples]); // even: one ring exactly on the waist
            var stations = new double[count + 1];
            int sample = 0;
            for (int k = 0; k <= count; k++)
            {
                double target = monitor[samples] * k / count;
                while (sample < samples - 1 && monitor[sample + 1] < target) sample++;
                double span = monitor[sample + 1] - monitor[sample];
                double f = span > 0.0 ? (target - monitor[sample]) / span : 0.0;
                double x = -1.0 + 2.0 * (sample + f) / samples;
                stations[k] = zoneCenter + 0.5 * zoneLength * x;
            }
            stations[count / 2] = zoneCenter;
            return stations;
        }

        private static int[] Uniform(int segmentCount, int ringsPerSegment)
        {
            if (segmentCount < 1)
                throw new ArgumentOutOfRangeException(nameof(segmentCount), segmentCount, "segmentCount must be in [1, +inf).");
            Require.InRange(ringsPerSegment, 1, MaxRingsPerSegment, nameof(ringsPerSegment));
            int[] counts = new int[segmentCount];
            Array.Fill(counts, ringsPerSegment);
            return counts;
        }
    }
}
