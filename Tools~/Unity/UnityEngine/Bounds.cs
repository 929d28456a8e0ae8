namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Bounds: an axis-aligned bounding box.</summary>
    public struct Bounds
    {
        /// <summary>Creates a new Bounds.</summary>
        public Bounds(Vector3 center, Vector3 size) => throw Shim.NotRun;

        /// <summary>The center of the bounding box.</summary>
        public Vector3 center { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The total size of the box. This is always twice as large as the extents.</summary>
        public Vector3 size { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Sets the bounds to the min and max value of the box.</summary>
        public void SetMinMax(Vector3 min, Vector3 max) => throw Shim.NotRun;
    }
}
