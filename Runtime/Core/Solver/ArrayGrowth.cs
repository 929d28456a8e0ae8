using System;

namespace HookeRope.Solver
{
    /// <summary>Growth rule shared by the append-only parallel arrays of pins, loads and colliders (never used in a step).</summary>
    internal static class ArrayGrowth
    {
        /// <summary>New capacity (elements) for full arrays holding count elements: double, at least 4.</summary>
        public static int NextCapacity(int count) => Math.Max(4, count * 2);
    }
}
