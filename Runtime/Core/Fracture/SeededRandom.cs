namespace HookeRope.Fracture
{
    /// <summary>
    /// Deterministic, platform-independent hash-based random numbers (integer arithmetic only), so the
    /// same seed gives the same burr on every machine. Stateless: each value is a hash of its inputs.
    /// </summary>
    internal static class SeededRandom
    {
        /// <summary>A well-mixed 32-bit hash of a seed and two integer keys (a finalizer of the murmur3 kind).</summary>
        public static uint Hash(uint seed, int keyA, int keyB)
        {
            uint h = seed * 0x9E3779B1u;
            h ^= unchecked((uint)keyA) * 0x85EBCA77u;
            h = (h << 13) | (h >> 19);
            h ^= unchecked((uint)keyB) * 0xC2B2AE3Du;
            h ^= h >> 16;
            h *= 0x7FEB352Du;
            h ^= h >> 15;
            h *= 0x846CA68Bu;
            h ^= h >> 16;
            return h;
        }

        /// <summary>A float in [0, 1) from the hash of a seed and two keys (24 random bits).</summary>
        public static float Unit(uint seed, int keyA, int keyB) => (Hash(seed, keyA, keyB) >> 8) * (1f / 16777216f);
    }
}
