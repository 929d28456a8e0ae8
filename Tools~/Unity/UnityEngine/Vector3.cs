namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Vector3.</summary>
    public struct Vector3
    {
        /// <summary>X component of the vector.</summary>
        public float x;
        /// <summary>Y component of the vector.</summary>
        public float y;
        /// <summary>Z component of the vector.</summary>
        public float z;

        /// <summary>Creates a new vector with given x, y, z components.</summary>
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
    }
}
