using System;
using HookeRope.Fracture;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope.Geometry
{
    /// <summary>
    /// The tube mesh of a <see cref="RopeSimulation"/>: its ring layout (refined around the Zone-mode neck), the
    /// builder and the ring-radius scratch. Allocates only when the topology settings, the neck mode, the defect or
    /// the zone change (or the model is rebuilt); the fill itself is allocation-free.
    /// </summary>
    internal sealed class RopeMesh
    {
        private readonly RopeSimulation simulation;
        private TubeMeshBuilder builder;
        private DanglingEnds dangling;
        private float[] ringRadii = Array.Empty<float>();
        private int rings;
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
        internal ReadOnlySpan<float> RingRadii => ringRadii;

        /// <summary>Drops the builder (the model or rest geometry changed): the next call rebuilds it.</summary>
        internal void Invalidate() => builder = null;

        /// <summary>Counts a topology change that the builder cannot see (a break).</summary>
        internal void TopologyChanged() => TopologyVersion++;

        internal int GetVertexCount() => Ensure().GetVertexCount(simulation.Rope.BrokenSegments);

        internal int GetIndexCount() => Ensure().GetIndexCount(simulation.Rope.BrokenSegments);

        /// <summary>
        /// Fills the mesh from positions in the caller's frame; ring radii are multiplied by <paramref name="radiusScale"/>.
        /// With <paramref name="frame"/> (where that frame sits in the rope's world) the ring centres are kept out of
        /// the rope's colliders; without it they are not checked.
        /// </summary>
        internal TubeMeshUpdate Fill(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            TubeVertex[] vertices, int[] indices, float radiusScale, MeshFrame? frame)
        {
            TubeMeshBuilder b = Ensure();
            ComputeRingRadii(b.Layout, radiusScale);
            Rope rope = simulation.Rope;
            if (rope.BrokenSegmentCount > 0) ComputeDanglingEnds(rope, radiusScale);
            b.SetContactColliders(frame.HasValue ? rope : null, frame.GetValueOrDefault());
            return b.BuildWithRingRadii(x, y, z, rope.RestLengths, ringRadii, rope.BrokenSegments, vertices, indices);
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

        private void ComputeRingRadii(RingLayout layout, float radiusScale)
        {
            RadiusModel model = simulation.RadiusModel;
            if (model != null && model.IsActive)
                model.FillRadiiAt(layout.RingSegments, layout.RingFractions, ringRadii);
            else
                Array.Fill(ringRadii, simulation.RestRadius);
            if (radiusScale != 1f)
                for (int k = 0; k < ringRadii.Length; k++) ringRadii[k] *= radiusScale;
        }

        private TubeMeshBuilder Ensure()
        {
            TubeMeshSettings s = Settings;
            RadiusSettings r = simulation.RadiusSettings;
            RadiusModel model = simulation.RadiusModel;
            bool zoneNeck = r != null && r.Necking && r.NeckMode == NeckMode.Zone && model != null;
            float defectPosition = r == null ? 0f : r.DefectPosition;
            float zoneDiameters = r == null ? 0f : r.NeckZoneDiameters;
            if (builder != null
                && builder.RadialSegments == s.RadialSegments
                && rings == s.RingsPerSegment
                && caps == s.CapEnds
                && burr == s.Burr.Enabled
                && zoneLayout == zoneNeck
                && defect == defectPosition
                && zone == zoneDiameters
                && restRadius == simulation.RestRadius
                && fibreDensity == s.Burr.FibreDensity)
                return builder;
            rings = s.RingsPerSegment;
            caps = s.CapEnds;
            burr = s.Burr.Enabled;
            zoneLayout = zoneNeck;
            defect = defectPosition;
            zone = zoneDiameters;
            restRadius = simulation.RestRadius;
            fibreDensity = s.Burr.FibreDensity;
            Rope rope = simulation.Rope;
            RingLayout layout = zoneNeck
                ? RingLayout.Adapted(rope.RestLengths, s.RingsPerSegment, model.DefectRestArc, model.NeckZoneRestLength, simulation.RestRadius, s.RadialSegments)
                : new RingLayout(rope.SegmentCount, s.RingsPerSegment);
            builder = new TubeMeshBuilder(s, layout, restRadius);
            dangling = new DanglingEnds(rope.SegmentCount);
            builder.SetDanglingEnds(dangling);
            ringRadii = new float[layout.RingCount];
            TopologyVersion++;
            return builder;
        }
    }
}
