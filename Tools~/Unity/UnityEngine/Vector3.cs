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

        /// <summary>Shorthand for writing Vector3(0, 0, 0).</summary>
        public static Vector3 zero => throw Shim.NotRun;

        /// <summary>Shorthand for writing Vector3(0, 1, 0).</summary>
        public static Vector3 up => throw Shim.NotRun;

        /// <summary>Returns the length of this vector.</summary>
        public float magnitude => throw Shim.NotRun;

        /// <summary>Returns the distance between a and b (same as (a - b).magnitude).</summary>
        public static float Distance(Vector3 a, Vector3 b) => throw Shim.NotRun;

        /// <summary>Adds two vectors.</summary>
        public static Vector3 operator +(Vector3 a, Vector3 b) => throw Shim.NotRun;

        /// <summary>Subtracts one vector from another.</summary>
        public static Vector3 operator -(Vector3 a, Vector3 b) => throw Shim.NotRun;

        /// <summary>Multiplies a vector by a number.</summary>
        public static Vector3 operator *(Vector3 a, float d) => throw Shim.NotRun;
    }
}
