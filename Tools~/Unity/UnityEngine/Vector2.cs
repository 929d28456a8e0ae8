namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.Vector2: a 2D vector of floats (only what the package's tests read: the fields and the constructor).</summary>
    public struct Vector2
    {
        /// <summary>X component of the vector.</summary>
        public float x;

        /// <summary>Y component of the vector.</summary>
        public float y;

        /// <summary>Constructs a new vector with given x, y components.</summary>
        public Vector2(float x, float y) { this.x = x; this.y = y; }
    }
}
