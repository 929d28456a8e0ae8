using System;
using HookeRope.Fracture;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope.Geometry
{
    /// <summary>
    /// The tube mesh of a <see cref="RopeSimulation"/>: its ring layout (adaptive by default: placed by need before each
    /// fill, with the Zone neck's stations while it necks; else uniform, refined around the Zone-mode neck), the builder
    /// and the ring radii. The ring radii are recomputed only when the layout, the radius model's profile
    /// (<see cref="RadiusModel.RadiiVersion"/>) or the radius scale changed. Allocates only when the topology settings,
    /// the neck mode, the defect or the zone change (or the model is rebuilt): the ring storage is made for the ring
    /// budget's most rings (<see cref="AdaptiveRings.MostRings"/>) with the builder; the fill itself is allocation-free.
    /// </summary>
    internal sealed class RopeMesh
    {
        private readonly RopeSimulation simulation;
        private TubeMeshBuilder builder;
        // the builder of the other side count, kept while only the side count changed (ViewDetail.RadialSegments switches
        // a far rope between two), so switching back allocates nothing
        private TubeMeshBuilder spare;
        private DanglingEnds dangling;
        private float[] ringRadii = Array.Empty<float>();
        private int ringCount;
        private int radiiLayoutVersion = -1;
        private int radiiModelVersion = -1;
        private float radiiScale = float.NaN;
        private RadiusModel radiiModel;
        private int filledVertices = -1, filledIndices = -1;
        private int rings;
        private bool adaptive;
        private bool caps;
        private bool burr;
        private bool zoneLayout;
        private float defect;
        private float zone;
        private float restRadius;
        private float fibreDensity;

        internal RopeMesh(RopeSimulation simulation, TubeMeshSettings settings)
        {
            this.simulation = simulation;
            Settings = settings;
        }

        /// <summary>Mesh settings (topology values are picked up at the next fill or count).</summary>
        internal TubeMeshSettings Settings { get; }

        /// <summary>Incremented whenever the topology changes (a break, new mesh settings, a new layout).</summary>
        internal int TopologyVersion { get; private set; }

        /// <summary>The ring layout of the current builder.</summary>
        internal RingLayout Layout => Ensure().Layout;

        /// <summary>Radius at each ring in metres after the last fill.</summary>
        internal ReadOnlySpan<float> RingRadii => new ReadOnlySpan<float>(ringRadii, 0, ringCount);

        /// <summary>Times the ring radii were computed (a fill whose layout, model profile and scale were unchanged skips it).</summary>
        internal int RingRadiusFills { get; private set; }

        /// <summary>The builder (made on first use), for the package's tests and tools.</summary>
        internal TubeMeshBuilder Builder => Ensure();

        /// <summary>Drops the builder (the model or rest geometry changed): the next call rebuilds it.</summary>
        internal void Invalidate()
        {
            builder = null;
            spare = null;
        }

        /// <summary>Counts a topology change that the builder cannot see (a break).</summary>
        internal void TopologyChanged() => TopologyVersion++;

        internal int GetVertexCount() => Ensure().GetVertexCount(simulation.Rope.BrokenSegments);

        internal int GetIndexCount() => Ensure().GetIndexCount(simulation.Rope.BrokenSegments);

        internal int GetVertexCapacity() => Ensure().GetVertexCapacity(simulation.Rope.BrokenSegments);

        internal int GetIndexCapacity() => Ensure().GetIndexCapacity(simulation.Rope.BrokenSegments);

        /// <summary>
        /// Fills the mesh into <paramref name="vertices"/> or, when it is null, <paramref name="leanVertices"/> from positions
        /// in the caller's frame; ring radii are multiplied by <paramref name="radiusScale"/>.
        /// With <paramref name="frame"/> (where that frame sits in the rope's world) the ring centres are kept out of
        /// the rope's colliders; without it they are not checked.
        /// </summary>
        internal TubeMeshUpdate Fill(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            TubeVertex[] vertices, LeanTubeVertex[] leanVertices, int[] indices, float radiusScale, MeshFrame? frame)
        {
            TubeMeshBuilder b = Ensure();
            Rope rope = simulation.Rope;
            if (b.IsAdaptive)
                b.PlanRings(x, y, z, rope.BrokenSegments, NeckActive(), simulation.RestRadius * radiusScale,
                    vertices?.Length ?? leanVertices?.Length ?? 0, indices?.Length ?? 0);
            ComputeRingRadii(b.Layout, radiusScale);
            if (rope.BrokenSegmentCount > 0) ComputeDanglingEnds(rope, radiusScale);
            b.SetContactColliders(frame.HasValue ? rope : null, frame.GetValueOrDefault());
            TubeMeshUpdate update = b.BuildWithRingRadii(x, y, z, rope.RestLengths, RingRadii, rope.BrokenSegments, vertices, leanVertices, indices);
            // an adaptive budget that moved: the counts differ from the last fill's (re-query sizes, re-upload indices)
            if (filledVertices >= 0 && (update.VertexCount != filledVertices || update.IndexCount != filledIndices)) TopologyVersion++;
            filledVertices = update.VertexCount;
            filledIndices = update.IndexCount;
            return update;
        }

        /// <summary>Each broken segment's halves: relaxed, half its rest length each, ending on the cut's radius (caller units).</summary>
        private void ComputeDanglingEnds(Rope rope, float radiusScale)
        {
            RadiusModel model = simulation.RadiusModel;
            bool modelled = model != null && model.IsActive;
            float r = simulation.RestRadius;
            ReadOnlySpan<bool> broken = rope.BrokenSegments;
            ReadOnlySpan<float> rest = rope.RestLengths;
            for (int j = 0; j < broken.Length; j++)
            {
                if (!broken[j]) continue;
                float lower = modelled ? model.BrokenEndRadius(j, false) : r;
                float upper = modelled ? model.BrokenEndRadius(j, true) : r;
                dangling.Set(j, DanglingEnds.Cut * rest[j] * radiusScale, lower * radiusScale, upper * radiusScale);
            }
        }

        /// <summary>True while the Zone neck is present (its stations are then drawn by an adaptive layout).</summary>
        private bool NeckActive() => zoneLayout && simulation.RadiusModel != null && simulation.RadiusModel.NeckDepth > 0f;

        /// <summary>The radius at every ring (m, times <paramref name="radiusScale"/>), skipped while the layout, the model's profile and the scale are unchanged.</summary>
        private void ComputeRingRadii(RingLayout layout, float radiusScale)
        {
            RadiusModel model = simulation.RadiusModel;
            bool modelled = model != null && model.IsActive;
            int count = layout.RingCount;
            int modelVersion = modelled ? model.RadiiVersion : -2;
            if (count == ringCount && layout.Version == radiiLayoutVersion && modelVersion == radiiModelVersion
                && ReferenceEquals(model, radiiModel) && radiusScale.Equals(radiiScale))
                return;
            if (ringRadii.Length < count) ringRadii = new float[Math.Max(count, 2 * ringRadii.Length)];
            RingRadiusFills++;
            ringCount = count;
            radiiLayoutVersion = layout.Version;
            radiiModelVersion = modelVersion;
            radiiModel = model;
            radiiScale = radiusScale;
            var radii = new Span<float>(ringRadii, 0, count);
            if (modelled)
                model.FillRadiiAt(layout.RingSegments, layout.RingFractions, radii);
            else
                radii.Fill(simulation.RestRadius);
            if (radiusScale != 1f)
                for (int k = 0; k < count; k++) radii[k] *= radiusScale;
        }

        private TubeMeshBuilder Ensure()
        {
            TubeMeshSettings s = Settings;
            RadiusSettings r = simulation.RadiusSettings;
            RadiusModel model = simulation.RadiusModel;
            bool zoneNeck = r != null && r.Necking && r.NeckMode == NeckMode.Zone && model != null;
            float defectPosition = r == null ? 0f : r.DefectPosition;
            float zoneDiameters = r == null ? 0f : r.NeckZoneDiameters;
            bool sameButSides = builder != null
                && adaptive == s.AdaptiveRings
                && rings == s.RingsPerSegment
                && caps == s.CapEnds
                && burr == s.Burr.Enabled
                && zoneLayout == zoneNeck
                && defect == defectPosition
                && zone == zoneDiameters
                && restRadius == simulation.RestRadius
                && fibreDensity == s.Burr.FibreDensity;
            if (sameButSides && builder.RadialSegments == s.RadialSegments) return builder;
            Rope rope = simulation.Rope;
            if (sameButSides && spare != null && spare.RadialSegments == s.RadialSegments)
            {
                // back to the other side count: its builder again, every vertex written anew (the buffers hold the other's)
                (builder, spare) = (spare, builder);
                builder.ForgetLastBuild();
                builder.PrimeRings(rope.PositionX, rope.PositionY, rope.PositionZ, rope.BrokenSegments, NeckActive(), simulation.RestRadius);
                if (ringRadii.Length < builder.MostRings) ringRadii = new float[builder.MostRings];
                ResetFillState();
                return builder;
            }
            spare = sameButSides ? builder : null;
            rings = s.RingsPerSegment;
            adaptive = s.AdaptiveRings;
            caps = s.CapEnds;
            burr = s.Burr.Enabled;
            zoneLayout = zoneNeck;
            defect = defectPosition;
            zone = zoneDiameters;
            restRadius = simulation.RestRadius;
            fibreDensity = s.Burr.FibreDensity;
            if (s.AdaptiveRings)
            {
                RingLayout stations = zoneNeck
                    ? RingLayout.Adapted(rope.RestLengths, 1, model.DefectRestArc, model.NeckZoneRestLength, simulation.RestRadius, s.RadialSegments)
                    : null;
                builder = TubeMeshBuilder.Adaptive(s, rope.SegmentCount, restRadius, stations);
                builder.PrimeRings(rope.PositionX, rope.PositionY, rope.PositionZ, rope.BrokenSegments, NeckActive(), simulation.RestRadius);
            }
            else
            {
                RingLayout layout = zoneNeck
                    ? RingLayout.Adapted(rope.RestLengths, s.RingsPerSegment, model.DefectRestArc, model.NeckZoneRestLength, simulation.RestRadius, s.RadialSegments)
                    : new RingLayout(rope.SegmentCount, s.RingsPerSegment);
                builder = new TubeMeshBuilder(s, layout, restRadius);
            }
            // the spare shares the dangling ends and the ring radii (sized for the larger)
            if (spare == null) dangling = new DanglingEnds(rope.SegmentCount);
            builder.SetDanglingEnds(dangling);
            if (spare == null || ringRadii.Length < builder.MostRings) ringRadii = new float[builder.MostRings];
            ResetFillState();
            return builder;
        }

        /// <summary>A new builder in place: the ring radii and the fill counts are recomputed, the topology counted as changed.</summary>
        private void ResetFillState()
        {
            ringCount = 0;
            radiiLayoutVersion = -1;
            filledVertices = -1;
            filledIndices = -1;
            TopologyVersion++;
        }
    }
}
