using System;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Places the rings of a tube by need (<see cref="RingNeed"/>): at least one per segment (a ring on every particle,
    /// so every simulated point is drawn and the radius profile is exact between them), more where the centre line
    /// bends, up to <see cref="MaxRingsPerSegment"/>, and, while a Zone neck is present, the neck's own stations in the
    /// segments under it. The topology is the number of rings of each unbroken piece (its budget), not where they sit:
    /// every build deals exactly the budget out to the piece's segments by need, so the index buffer stays the same while
    /// the rope moves. Budgets come in steps of 1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12 and 16 rings per segment, so the
    /// topology changes rarely: a budget grows to the smallest step that holds the demand when the demand exceeds it, and
    /// after <see cref="CalmBuilds"/> consecutive builds in which the demand with 10 % more rings per segment fits the step
    /// below with a quarter of that step's excess to spare (hysteresis) it shrinks to the smallest step that holds the
    /// largest such demand of those builds;
    /// the extra rings of a step go where the need is largest. A change takes effect at the next build whose buffers hold it, so callers that query the
    /// counts before every fill (RopeMeshRenderer, RopeWorld) see it one build later. Allocation-free after construction.
    /// <para>
    /// The ring budget (issue 18, "0 bytes per update"): a piece's budget never exceeds its cap, <see cref="MaxMeanRingsPerSegment"/>
    /// rings per segment plus the neck's stations in the segments that hold them (<see cref="CapOfPiece"/>), so the whole
    /// rope never holds more than <see cref="MostRings"/> = Σ caps + 1 rings, whatever the breaks: storage made for that
    /// once, at creation, never grows. When a piece's demand exceeds its cap (a whipping rope), the budget stays at the cap
    /// and the rings are redistributed within it by need (every need scaled by one common factor, at least one ring per
    /// segment, at most <see cref="MaxRingsPerSegment"/>), never allocated: the drawn surface then exceeds the tolerance
    /// where it bends most, evenly along the piece. A piece whose demand fits its cap gets exactly the budget it got before
    /// the cap (the step ladder below the cap is unchanged), so taut and gently curved ropes draw the same bits.
    /// </para>
    /// </summary>
    internal sealed class AdaptiveRings
    {
        /// <summary>Largest number of rings the adaptive placement puts in one segment.</summary>
        public const int MaxRingsPerSegment = 16;

        /// <summary>
        /// Most rings per segment, on average over an unbroken piece, that the adaptive placement draws outside the neck's
        /// stations: the ring budget's cap (a 64-segment rope holds at most 64 × 8 + 1 = 513 rings).
        /// </summary>
        public const int MaxMeanRingsPerSegment = 8;

        /// <summary>Builds in a row with a surplus beyond the hysteresis band before a budget shrinks (1 s at 90 Hz).</summary>
        public const int CalmBuilds = 90;

        private readonly int n;
        private readonly RingLayout zone;
        private readonly float polygonTolerance;
        private float toleranceScale = RopeParameters.RingTolerance.Default;
        private readonly int[] capBefore;
        private readonly float[] need;
        private readonly int[] counts;
        private readonly int[] budget;
        private readonly int[] next;
        private readonly int[] calm;
        private readonly int[] calmPeak;
        private readonly bool[] pieceBroken;
        private readonly float[] lastX, lastY, lastZ;
        private bool hasLast;
        private bool lastZoneActive;
        private float lastRadius;
        private readonly bool[] forced;

        /// <summary>
        /// Placement for <paramref name="segmentCount"/> segments and <paramref name="radialSegments"/> sides (which set the
        /// tolerance, <see cref="RingNeed.Tolerance"/>); <paramref name="neckStations"/> (null = none) is a layout with one
        /// ring per segment outside a neck zone and the zone's stations inside it (<see cref="RingLayout.Adapted"/> with one
        /// ring per segment): its segments with more than one ring are drawn with exactly those rings while the neck is active.
        /// </summary>
        public AdaptiveRings(int segmentCount, int radialSegments, RingLayout neckStations)
            : this(segmentCount, radialSegments, neckStations, MaxMeanRingsPerSegment)
        {
        }

        /// <summary>
        /// Placement as above with a ring budget of <paramref name="meanRingsPerSegment"/> rings per segment on average
        /// (1 … <see cref="MaxRingsPerSegment"/>; the package uses <see cref="MaxMeanRingsPerSegment"/>, the tests compare
        /// with <see cref="MaxRingsPerSegment"/>, which never caps: the placement as it was before the budget), at
        /// <see cref="ToleranceScale"/> 1 until it is set.
        /// </summary>
        internal AdaptiveRings(int segmentCount, int radialSegments, RingLayout neckStations, int meanRingsPerSegment)
        {
            Require.InRange(meanRingsPerSegment, 1, MaxRingsPerSegment, nameof(meanRingsPerSegment));
            if (segmentCount < 1)
                throw new ArgumentOutOfRangeException(nameof(segmentCount), segmentCount, "segmentCount must be in [1, +inf).");
            if (neckStations != null && neckStations.SegmentCount != segmentCount)
                throw new ArgumentException("neckStations must have SegmentCount = " + segmentCount + " segments.", nameof(neckStations));
            n = segmentCount;
            zone = neckStations;
            polygonTolerance = RingNeed.Tolerance(radialSegments);
            capBefore = new int[n + 1];
            for (int j = 0; j < n; j++)
                capBefore[j + 1] = capBefore[j] + meanRingsPerSegment + (zone != null && zone.RingsIn(j) > 1 ? zone.RingsIn(j) : 0);
            need = new float[n];
            counts = new int[n];
            budget = new int[n];
            next = new int[n];
            calm = new int[n];
            calmPeak = new int[n];
            pieceBroken = new bool[n];
            forced = new bool[n];
            lastX = new float[n + 1];
            lastY = new float[n + 1];
            lastZ = new float[n + 1];
            Array.Fill(counts, 1);
            budget[0] = n;
            next[0] = n;
        }

        /// <summary>
        /// Most rings a layout of this placement can hold, intact or broken: the sum of the caps of every segment
        /// (<see cref="CapOfPiece"/> of the whole rope) + the end ring, so storage made for it never grows.
        /// </summary>
        public int MostRings => capBefore[n] + 1;

        /// <summary>
        /// Most rings the segments [a, b) of one unbroken piece may hold: the constructor's mean rings per segment
        /// plus the neck's stations in each segment that holds more than one. A piece's budget never exceeds it.
        /// </summary>
        public int CapOfPiece(int a, int b) => capBefore[b] - capBefore[a];

        /// <summary>
        /// True when the cap limited the last plan's budget of some piece: the budget step that holds its demand is above its
        /// cap, so the piece keeps the cap and its rings are redistributed within it (false: every budget is as without the cap).
        /// </summary>
        public bool BudgetHit { get; private set; }

        /// <summary>The neck's stations (null = none): a broken segment keeps them (<see cref="KeepsNeckStations"/>).</summary>
        public RingLayout NeckStations => zone;

        /// <summary>True when broken segment <paramref name="segment"/> is drawn with the neck's stations (its dangling halves show the half-necks), else with one ring.</summary>
        public bool KeepsNeckStations(int segment) => zone != null && zone.RingsIn(segment) > 1;

        /// <summary>Most rings a layout of this placement puts in one segment (the cap, or more neck stations).</summary>
        public int MostRingsInOneSegment
        {
            get
            {
                int most = MaxRingsPerSegment;
                if (zone != null)
                    for (int j = 0; j < n; j++) most = Math.Max(most, zone.RingsIn(j));
                return most;
            }
        }

        /// <summary>Tolerance of the drawn surface as a fraction of the drawn radius (<see cref="RingNeed.Tolerance"/> times <see cref="ToleranceScale"/>).</summary>
        public float ToleranceFraction => polygonTolerance * toleranceScale;

        /// <summary>
        /// The tolerance as a multiple of <see cref="RingNeed.Tolerance"/> (<see cref="TubeMeshSettings.RingTolerance"/>,
        /// range <see cref="RopeParameters.RingTolerance"/>). A new value applies at the next <see cref="Plan"/>, which then
        /// measures the needs again whatever else changed; the budgets follow as for any change of need (up at once, down
        /// after a calm spell), within the storage made for <see cref="MostRings"/>, so a new value allocates nothing.
        /// </summary>
        public float ToleranceScale
        {
            get => toleranceScale;
            set
            {
                RopeParameters.Check(value, RopeParameters.RingTolerance.Row);
                if (value.Equals(toleranceScale)) return;
                toleranceScale = value;
                hasLast = false;
            }
        }

        /// <summary>Incremented whenever a budget that the counts report changes (a topology change at the next build).</summary>
        public int BudgetVersion { get; private set; }

        /// <summary>Rings of the unbroken piece [a, b) that the counts report (its next budget + its end ring).</summary>
        public int RingsOfPiece(int a, ReadOnlySpan<bool> brokenSegments)
        {
            SyncPieces(brokenSegments);
            return next[a] + 1;
        }

        /// <summary>
        /// Sets the budgets to what the positions need now (no hysteresis): call once when the mesh is made, so that the
        /// first build needs no catching up. Same arguments as <see cref="Plan"/>.
        /// </summary>
        public void Prime(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, ReadOnlySpan<bool> brokenSegments,
            bool zoneActive, float radius)
        {
            SyncPieces(brokenSegments);
            Measure(x, y, z, brokenSegments, radius);
            int segment = 0;
            while (NextPiece(brokenSegments, ref segment, out int a, out int b))
            {
                int demand = Demand(a, b, zoneActive && zone != null, 1f);
                int target = Target(demand, a, b);
                if (next[a] != target || budget[a] != target) BudgetVersion++;
                next[a] = target;
                budget[a] = target;
                calm[a] = 0;
            }
            hasLast = false;
        }

        /// <summary>True when some piece's next budget differs from the budget of the last build (a topology change pending).</summary>
        public bool BudgetPending(ReadOnlySpan<bool> brokenSegments)
        {
            SyncPieces(brokenSegments);
            int segment = 0;
            while (NextPiece(brokenSegments, ref segment, out int a, out _))
                if (next[a] != budget[a]) return true;
            return false;
        }

        /// <summary>
        /// Writes this build's rings into <paramref name="layout"/>: with <paramref name="takeNext"/> (the caller's buffers
        /// hold what the counts reported) the next budgets become the budgets, else the previous ones stay; each budget is
        /// dealt out by need for a drawn radius of <paramref name="radius"/> (m), then the next budgets are updated. Returns
        /// false (layout untouched) when nothing it depends on changed: positions (bitwise), broken flags, neck state, radius
        /// and budgets.
        /// </summary>
        public bool Plan(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, ReadOnlySpan<bool> brokenSegments,
            bool zoneActive, float radius, bool takeNext, RingLayout layout)
        {
            bool piecesChanged = SyncPieces(brokenSegments);
            bool budgetsMove = takeNext && BudgetPending(brokenSegments);
            bool positionsChanged = !hasLast || !Same(x, lastX) || !Same(y, lastY) || !Same(z, lastZ);
            if (!positionsChanged && !piecesChanged && zoneActive == lastZoneActive && radius == lastRadius && !budgetsMove)
            {
                UpdateNextBudgets(brokenSegments, zoneActive);
                return false;
            }
            if (positionsChanged || piecesChanged || radius != lastRadius) Measure(x, y, z, brokenSegments, radius);
            x.CopyTo(lastX); y.CopyTo(lastY); z.CopyTo(lastZ);
            hasLast = true;
            lastZoneActive = zoneActive;
            lastRadius = radius;

            int segment = 0;
            while (NextPiece(brokenSegments, ref segment, out int a, out int b))
            {
                if (takeNext) budget[a] = next[a];
                Deal(a, b, budget[a], zoneActive);
            }
            Write(brokenSegments, layout);
            UpdateNextBudgets(brokenSegments, zoneActive);
            return true;
        }

        /// <summary>True when the last plan drew the neck's stations in segment <paramref name="segment"/>.</summary>
        public bool DrawsNeckStations(int segment) => forced[segment];

        private void UpdateNextBudgets(ReadOnlySpan<bool> brokenSegments, bool zoneActive)
        {
            int segment = 0;
            BudgetHit = false;
            while (NextPiece(brokenSegments, ref segment, out int a, out int b))
            {
                int segments = b - a;
                bool withZone = zoneActive && zone != null;
                int demand = Demand(a, b, withZone, 1f);
                if (Step(demand, segments) > CapOfPiece(a, b)) BudgetHit = true;
                int current = budget[a];
                int wanted = next[a];
                int comfortable = demand > current ? 0 : Demand(a, b, withZone, ShrinkMargin);
                if (demand > current) { wanted = Target(demand, a, b); calm[a] = 0; }
                else if (comfortable <= ShrinkBelow(current, segments))
                {
                    // shrink to what the whole calm spell needed (with the margin), not to this build's demand
                    calmPeak[a] = calm[a] == 0 ? comfortable : Math.Max(calmPeak[a], comfortable);
                    if (++calm[a] >= CalmBuilds) { wanted = Target(calmPeak[a], a, b); calm[a] = 0; }
                }
                else calm[a] = 0;
                if (wanted != next[a]) { next[a] = wanted; BudgetVersion++; }
            }
        }

        /// <summary>Ring budgets per segment of a piece, as multiples of one ring per segment: a budget is one of these.</summary>
        private static readonly float[] Steps = { 1f, 1.25f, 1.5f, 2f, 2.5f, 3f, 4f, 5f, 6f, 8f, 10f, 12f, MaxRingsPerSegment };

        /// <summary>
        /// The smallest budget step of piece [a, b) that holds <paramref name="demand"/> rings, or the piece's cap
        /// (<see cref="CapOfPiece"/>) when that step is above it.
        /// </summary>
        private int Target(int demand, int a, int b) => Math.Min(Step(demand, b - a), CapOfPiece(a, b));

        /// <summary>The smallest budget step of a piece of <paramref name="segments"/> segments that holds <paramref name="demand"/> rings.</summary>
        private static int Step(int demand, int segments)
        {
            for (int i = 0; i < Steps.Length; i++)
            {
                int budget = (int)MathF.Ceiling(segments * Steps[i]);
                if (budget >= demand) return budget;
            }
            return segments * MaxRingsPerSegment;
        }

        /// <summary>Demand at or below which a piece with budget <paramref name="current"/> may shrink: the next step down, less a quarter of its excess over one ring per segment.</summary>
        private static int ShrinkBelow(int current, int segments)
        {
            int below = segments;
            for (int i = 0; i < Steps.Length; i++)
            {
                int budget = (int)MathF.Ceiling(segments * Steps[i]);
                if (budget >= current) break;
                below = budget;
            }
            return below - (below - segments) / 4;
        }

        /// <summary>Ring counts a piece must fit with this margin to shrink: 10 % more rings than needed (21 % less error).</summary>
        private const float ShrinkMargin = 1.1f;

        /// <summary>Rings piece [a, b) asks for now: the neck's stations where they are drawn, ⌈need × <paramref name="margin"/>⌉ (1 … max) elsewhere.</summary>
        private int Demand(int a, int b, bool withZone, float margin)
        {
            int demand = 0;
            if (!withZone)
            {
                // no neck stations: the needs alone, through a span of exactly the piece's segments
                ReadOnlySpan<float> needs = new ReadOnlySpan<float>(need, a, b - a);
                for (int i = 0; i < needs.Length; i++) demand += Rounded(needs[i] * margin);
                return demand;
            }
            for (int j = a; j < b; j++)
                demand += zone.RingsIn(j) > 1 ? zone.RingsIn(j) : Rounded(need[j] * margin);
            return demand;
        }

        private static int Rounded(float m)
        {
            if (!(m > 1f)) return 1;
            if (m >= MaxRingsPerSegment) return MaxRingsPerSegment;
            return (int)MathF.Ceiling(m);
        }

        /// <summary>Deals <paramref name="total"/> rings to the segments of piece [a, b) into <see cref="counts"/>.</summary>
        private void Deal(int a, int b, int total, bool zoneActive)
        {
            int fixedRings = 0, free = 0;
            bool withZone = zoneActive && zone != null;
            if (withZone)
            {
                for (int j = a; j < b; j++)
                    if (zone.RingsIn(j) > 1) fixedRings += zone.RingsIn(j); else free++;
                // the stations only when every other segment still keeps its ring
                if (fixedRings + free > total) withZone = false;
            }
            int left = total;
            int sum = 0;
            // spans of exactly the piece's segments (index i = j − a); a neck station's segment is held at its stations' count,
            // every other one gets its rounded need
            ReadOnlySpan<float> needs = new ReadOnlySpan<float>(need, a, b - a);
            Span<int> dealt = new Span<int>(counts, a, needs.Length).Slice(0, needs.Length);
            Span<bool> held = new Span<bool>(forced, a, needs.Length).Slice(0, needs.Length);
            for (int i = 0; i < needs.Length; i++)
            {
                int stations = withZone ? zone.RingsIn(a + i) : 0;
                held[i] = stations > 1;
                if (held[i]) { dealt[i] = stations; left -= stations; continue; }
                int count = Rounded(needs[i]);
                dealt[i] = count;
                sum += count;
            }
            if (sum > left) Shrink(a, b, left);
            Spread(a, b, left);
        }

        private bool IsFree(int j) => !forced[j];

        /// <summary>Scales the needs down (bisection on a common factor) until the free segments' rings fit into <paramref name="left"/>.</summary>
        private void Shrink(int a, int b, int left)
        {
            float low = 0f, high = 1f;
            for (int iteration = 0; iteration < 24; iteration++)
            {
                float s = 0.5f * (low + high);
                int sum = 0;
                for (int j = a; j < b; j++) if (IsFree(j)) sum += Rounded(need[j] * s);
                if (sum <= left) low = s; else high = s;
            }
            for (int j = a; j < b; j++) if (IsFree(j)) counts[j] = Rounded(need[j] * low);
        }

        /// <summary>Gives the free segments' surplus (<paramref name="left"/> − their rings) out in proportion to need, by cumulative rounding.</summary>
        private void Spread(int a, int b, int left)
        {
            // spans of exactly the piece's segments (index i = j − a)
            ReadOnlySpan<float> needs = new ReadOnlySpan<float>(need, a, b - a);
            ReadOnlySpan<bool> held = new ReadOnlySpan<bool>(forced, a, needs.Length).Slice(0, needs.Length);
            Span<int> dealt = new Span<int>(counts, a, needs.Length).Slice(0, needs.Length);
            int sum = 0;
            double weight = 0.0;
            for (int i = 0; i < needs.Length; i++)
            {
                if (held[i]) continue;
                sum += dealt[i];
                if (dealt[i] < MaxRingsPerSegment) weight += needs[i] + 0.01;
            }
            int surplus = left - sum;
            if (surplus <= 0 || weight <= 0.0) return;
            double cumulative = 0.0;
            int given = 0;
            for (int i = 0; i < needs.Length && given < surplus; i++)
            {
                if (held[i] || dealt[i] >= MaxRingsPerSegment) continue;
                cumulative += (needs[i] + 0.01) / weight * surplus;
                int share = (int)Math.Round(cumulative) - given;
                if (share > MaxRingsPerSegment - dealt[i]) share = MaxRingsPerSegment - dealt[i];
                if (share > surplus - given) share = surplus - given;
                if (share <= 0) continue;
                dealt[i] += share;
                given += share;
            }
            // what the caps turned away goes to the first segments with room
            for (int j = a; j < b && given < surplus; j++)
            {
                if (!IsFree(j)) continue;
                int room = Math.Min(MaxRingsPerSegment - counts[j], surplus - given);
                if (room <= 0) continue;
                counts[j] += room;
                given += room;
            }
        }

        private void Write(ReadOnlySpan<bool> brokenSegments, RingLayout layout)
        {
            bool hasBroken = brokenSegments.Length > 0;
            ReadOnlySpan<int> zoneSegments = zone != null ? zone.RingSegments : default;
            ReadOnlySpan<float> zoneFractions = zone != null ? zone.RingFractions : default;
            layout.Begin();
            for (int j = 0; j < n; j++)
            {
                // a broken segment keeps the neck's stations (its dangling halves draw the half-necks), else one ring
                if (hasBroken && brokenSegments[j] && !KeepsNeckStations(j)) { layout.Add(j, 0f); continue; }
                if (hasBroken && brokenSegments[j] || forced[j])
                {
                    int first = zone.FirstRing(j);
                    for (int k = first; k < first + zone.RingsIn(j); k++) layout.Add(zoneSegments[k], zoneFractions[k]);
                    continue;
                }
                // the run of uniform segments from j in one call
                int end = j + 1;
                while (end < n && !(hasBroken && brokenSegments[end]) && !forced[end]) end++;
                layout.AddUniformRuns(j, new ReadOnlySpan<int>(counts, j, end - j));
                j = end - 1;
            }
            layout.End();
        }

        private void Measure(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, ReadOnlySpan<bool> brokenSegments, float radius)
        {
            float ox = x[0], oy = y[0], oz = z[0];
            if (!float.IsFinite(ox) || !float.IsFinite(oy) || !float.IsFinite(oz)) ox = oy = oz = 0f;
            float r = float.IsFinite(radius) && radius > 1e-6f ? radius : 1e-6f;
            int segment = 0;
            while (NextPiece(brokenSegments, ref segment, out int a, out int b))
                RingNeed.OfPiece(a, b, x, y, z, ox, oy, oz, r, ToleranceFraction * r, MaxRingsPerSegment, need);
        }

        /// <summary>Re-derives the budgets when the broken flags changed: each new piece keeps the rings its segments had.</summary>
        private bool SyncPieces(ReadOnlySpan<bool> brokenSegments)
        {
            bool hasBroken = brokenSegments.Length > 0;
            // the usual case first, by a vectorised comparison of the flags: nothing changed
            ReadOnlySpan<bool> kept = new ReadOnlySpan<bool>(pieceBroken, 0, n);
            if (hasBroken ? brokenSegments.Length >= n && brokenSegments.Slice(0, n).SequenceEqual(kept) : kept.IndexOf(true) < 0)
                return false;
            bool changed = false;
            for (int j = 0; j < n; j++)
            {
                bool broken = hasBroken && brokenSegments[j];
                if (broken != pieceBroken[j]) { changed = true; pieceBroken[j] = broken; }
            }
            if (!changed) return false;
            int segment = 0;
            while (NextPiece(brokenSegments, ref segment, out int a, out int b))
            {
                int rings = 0;
                for (int j = a; j < b; j++) rings += counts[j];
                // a new piece may have held more than its own cap of its old piece's rings: it keeps at most its cap
                rings = Math.Min(rings, CapOfPiece(a, b));
                budget[a] = rings;
                next[a] = rings;
                calm[a] = 0;
            }
            BudgetVersion++;
            return true;
        }

        private bool NextPiece(ReadOnlySpan<bool> brokenSegments, ref int segment, out int a, out int b) =>
            RopePieces.Next(brokenSegments, n, ref segment, out a, out b);

        private static bool Same(ReadOnlySpan<float> now, float[] before) => RopePieces.SameBits(now, before);
    }
}
