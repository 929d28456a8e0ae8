using System;
using NUnit.Framework;
using NUnit.Framework.Constraints;

namespace UnityEngine.TestTools.Constraints
{
    /// <summary>
    /// Stand-in of UnityEngine.TestTools.Constraints.AllocatingGCMemoryConstraint: runs the delegate given to
    /// Assert.That and passes when it allocated GC memory (negate it with Is.Not to assert zero allocation). Unity
    /// counts the main thread's GC.Alloc profiler samples; the stand-in counts the calling thread's allocated bytes
    /// (GC.GetAllocatedBytesForCurrentThread), the same quantity on one thread.
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
            long before = GC.GetAllocatedBytesForCurrentThread();
            run();
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            return new ConstraintResult(this, "delegate allocating " + allocated + " bytes", allocated > 0);
        }
    }
}
