using HookeRope.Mathematics;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// The harness rig the manual's figures show (world metres, Y up, floor top at y = 0): an I-beam overhead along X,
    /// a floor with a drop hatch, a worker block (legs, torso, head) facing +Z with a D-ring on its back, and the
    /// anchor the self-wiring creates. The D-ring sits straight below the beam, <see cref="Gap"/> under its underside.
    /// </summary>
    public static class HarnessRig
    {
        /// <summary>Height of the beam's underside (m).</summary>
        public const float BeamUnderside = 3.05f;
        /// <summary>Height of the D-ring (m).</summary>
        public const float DRingHeight = 1.45f;
        /// <summary>Depth (z) of the D-ring centre: just behind the worker's back, under the beam's web (m).</summary>
        public const float DRingZ = 0.02f;
        /// <summary>Vertical distance D-ring → beam underside (m): where the upward ray hits the beam.</summary>
        public const float Gap = BeamUnderside - DRingHeight;
        /// <summary>Mass of the worker's Rigidbody (kg).</summary>
        public const float WorkerMass = 100f;

        /// <summary>Beam steel colour.</summary>
        public const uint Steel = 0x7D8793;
        /// <summary>Floor colour.</summary>
        public const uint Concrete = 0xC9C9C2;
        /// <summary>Worker torso colour.</summary>
        public const uint Jacket = 0x3C6EBE;
        /// <summary>Worker legs colour.</summary>
        public const uint Trousers = 0x2B3F66;
        /// <summary>Helmet colour.</summary>
        public const uint Helmet = 0xE6E8EC;
        /// <summary>D-ring colour.</summary>
        public const uint Metal = 0x3A3D44;
        /// <summary>Anchor (Transform) marker colour.</summary>
        public const uint AnchorGreen = 0x3FA05A;
        /// <summary>The rope's default tint (RopeParameters.Color: 0.93, 0.5, 0.12).</summary>
        public const uint RopeOrange = 0xED801F;

        /// <summary>The D-ring centre with the worker standing (m).</summary>
        public static Float3 DRing => new Float3(0f, DRingHeight, DRingZ);

        /// <summary>Where the upward ray from the D-ring meets the beam: the snapped anchor (m).</summary>
        public static Float3 SnappedAnchor => new Float3(0f, BeamUnderside, DRingZ);

        /// <summary>Adds the I-beam (bottom flange, web, top flange) along X.</summary>
        public static void AddBeam(FigureScene scene)
        {
            scene.AddBox(new Float3(0f, BeamUnderside + 0.012f, 0f), new Float3(1.9f, 0.012f, 0.075f), Steel);
            scene.AddBox(new Float3(0f, BeamUnderside + 0.11f, 0f), new Float3(1.9f, 0.086f, 0.007f), Steel);
            scene.AddBox(new Float3(0f, BeamUnderside + 0.208f, 0f), new Float3(1.9f, 0.012f, 0.075f), Steel);
        }

        /// <summary>Adds the floor slabs around the hatch under the worker, and the hatch slab itself when <paramref name="hatchClosed"/>.</summary>
        public static void AddFloor(FigureScene scene, bool hatchClosed)
        {
            const float top = 0f, half = 0.05f;
            float y = top - half;
            scene.AddBox(new Float3(-1.3f, y, 0.1f), new Float3(0.9f, half, 1.0f), Concrete);
            scene.AddBox(new Float3(1.1f, y, 0.1f), new Float3(0.7f, half, 1.0f), Concrete);
            scene.AddBox(new Float3(0f, y, -0.65f), new Float3(0.4f, half, 0.25f), Concrete);
            scene.AddBox(new Float3(0f, y, 0.95f), new Float3(0.4f, half, 0.15f), Concrete);
            if (hatchClosed) scene.AddBox(new Float3(0f, y, 0.15f), new Float3(0.4f, half, 0.5f), 0xB4B4AC);
        }

        /// <summary>Adds the worker with its D-ring at <paramref name="dRing"/> (the body moves with it).</summary>
        public static void AddWorker(FigureScene scene, Float3 dRing)
        {
            var o = dRing - DRing;
            scene.AddBox(o + new Float3(0f, 0.45f, 0.17f), new Float3(0.17f, 0.45f, 0.1f), Trousers);
            scene.AddBox(o + new Float3(0f, 1.23f, 0.17f), new Float3(0.22f, 0.33f, 0.13f), Jacket);
            scene.AddBox(o + new Float3(0f, 1.7f, 0.17f), new Float3(0.1f, 0.11f, 0.1f), Helmet);
            // harness: two back straps down from the D-ring
            scene.AddBox(o + new Float3(-0.07f, 1.25f, 0.035f), new Float3(0.02f, 0.25f, 0.006f), Metal);
            scene.AddBox(o + new Float3(0.07f, 1.25f, 0.035f), new Float3(0.02f, 0.25f, 0.006f), Metal);
            scene.AddTorus(dRing, new Float3(1f, 0f, 0f), new Float3(0f, 1f, 0f), 0.035f, 0.007f, Metal);
        }

        /// <summary>Adds the small cube that marks an anchor Transform at <paramref name="position"/>.</summary>
        public static void AddAnchor(FigureScene scene, Float3 position) =>
            scene.AddBox(position, new Float3(0.03f, 0.03f, 0.03f), AnchorGreen);
    }
}
