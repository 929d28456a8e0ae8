namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Quaternion.</summary>
    public struct Quaternion
    {
        /// <summary>X component of the Quaternion. Don't modify this directly unless you know quaternions inside out.</summary>
        public float x;
        /// <summary>Y component of the Quaternion. Don't modify this directly unless you know quaternions inside out.</summary>
        public float y;
        /// <summary>Z component of the Quaternion. Don't modify this directly unless you know quaternions inside out.</summary>
        public float z;
        /// <summary>W component of the Quaternion. Do not directly modify quaternions.</summary>
        public float w;

        /// <summary>Constructs new Quaternion with given x,y,z,w components.</summary>
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }

        /// <summary>The identity rotation (Read Only).</summary>
        public static Quaternion identity => throw Shim.NotRun;

        /// <summary>Returns a rotation that rotates z degrees around the z axis, x degrees around the x axis, and y degrees around the y axis.</summary>
        public static Quaternion Euler(float x, float y, float z) => throw Shim.NotRun;

        /// <summary>Rotates the point point with rotation.</summary>
        public static Vector3 operator *(Quaternion rotation, Vector3 point) => throw Shim.NotRun;
    }
}
