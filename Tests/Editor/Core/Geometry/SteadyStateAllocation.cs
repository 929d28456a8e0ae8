using System;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Bytes allocated on this thread by <c>repetitions</c> calls of an action, in steady state: the fewest over
    /// several rounds. The runtime itself may allocate once while it re-compiles a hot method (tiered JIT), which
    /// lands in one round; an allocation of the code under test lands in every round.
    /// </summary>
    internal static class SteadyStateAllocation
    {
        public static long Bytes(Action action, int repetitions, int rounds = 8)
        {
            for (int i = 0; i < repetitions; i++) action();
            long fewest = long.MaxValue;
            for (int round = 0; round < rounds; round++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                for (int i = 0; i < repetitions; i++) action();
                long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
                if (bytes < fewest) fewest = bytes;
            }
            return fewest;
        }
    }
}
