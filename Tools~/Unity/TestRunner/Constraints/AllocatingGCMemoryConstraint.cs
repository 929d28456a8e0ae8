using System;
using System.Runtime;
using NUnit.Framework;
using NUnit.Framework.Constraints;

namespace UnityEngine.TestTools.Constraints
{
    /// <summary>
    /// Stand-in of UnityEngine.TestTools.Constraints.AllocatingGCMemoryConstraint: runs the delegate given to
    /// Assert.That and passes when it allocated GC memory (negate it with Is.Not to assert zero allocation). Unity
    /// counts the main thread's GC.Alloc profiler samples; the stand-in counts the calling thread's allocated bytes
    /// (GC.GetAllocatedBytesForCurrentThread), the same quantity on one thread. That count is exact only without
    /// background GC: a concurrent gen-2 collection retires the thread's allocation context and the count then
    /// jumps by its unused space, so the constraint refuses to run unless the test process has concurrent GC off
    /// (GCSettings.LatencyMode is Batch; the test projects set ConcurrentGarbageCollection to false).
    /// </summary>
    public class AllocatingGCMemoryConstraint : Constraint
    {
        /// <summary>The constraint's description in failure messages.</summary>
        public override string Description => "allocates GC memory";

        /// <summary>Runs <paramref name="actual"/> (a TestDelegate or Action) and reports whether it allocated.</summary>
        public override ConstraintResult ApplyTo<TActual>(TActual actual)
        {
            Action run = actual switch
            {
                TestDelegate test => () => test(),
                Action action => action,
                _ => throw new ArgumentException("The actual value must be a TestDelegate or an Action, not " + (actual?.GetType().Name ?? "null") + ".", nameof(actual)),
            };
            if (GCSettings.LatencyMode != GCLatencyMode.Batch)
                throw new InvalidOperationException("Is.Not.AllocatingGCMemory() needs concurrent GC off (GCSettings.LatencyMode "
                    + GCSettings.LatencyMode + ", expected Batch): set <ConcurrentGarbageCollection>false</ConcurrentGarbageCollection> "
                    + "in the test project or DOTNET_gcConcurrent=0, or a background collection is counted as an allocation.");
            long before = GC.GetAllocatedBytesForCurrentThread();
            run();
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            return new ConstraintResult(this, "delegate allocating " + allocated + " bytes", allocated > 0);
        }
    }
}
