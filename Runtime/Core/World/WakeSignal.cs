using System.Threading;

namespace HookeRope.World
{
    /// <summary>
    /// A manual-reset signal for the world's hand-offs that never allocates, not even the first time a thread blocks
    /// on it. <see cref="ManualResetEventSlim"/> makes its lock object (24 bytes) at the first wait that blocks instead
    /// of spinning, which for a world's end-of-pass signal can be any pass, long after warm-up; this one makes its lock
    /// in the constructor. A waiter spins briefly (until the spin would yield) and then blocks on the lock with
    /// <see cref="Monitor.Wait(object)"/>; <see cref="Set"/> wakes every blocked waiter.
    /// </summary>
    internal sealed class WakeSignal
    {
        private readonly object gate = new object();
        private volatile bool isSet;
        private int blocked;

        /// <summary>True between <see cref="Set"/> and <see cref="Reset"/>.</summary>
        public bool IsSet => isSet;

        /// <summary>Sets the signal and wakes the threads blocked in <see cref="Wait"/>.</summary>
        public void Set()
        {
            isSet = true;
            // a full fence between the write above and the read below, as in Wait between its count and its check: either
            // the waiter sees the signal set, or this sees the waiter counted and pulses it under the lock
            Interlocked.MemoryBarrier();
            if (Volatile.Read(ref blocked) == 0) return;
            lock (gate) Monitor.PulseAll(gate);
        }

        /// <summary>Clears the signal (only while no thread waits on it).</summary>
        public void Reset() => isSet = false;

        /// <summary>Returns once the signal is set: at once when it is, after a short spin when it is set soon, else blocked until <see cref="Set"/>.</summary>
        public void Wait()
        {
            var spin = new SpinWait();
            while (!isSet)
            {
                if (spin.NextSpinWillYield)
                {
                    lock (gate)
                    {
                        Interlocked.Increment(ref blocked);
                        while (!isSet) Monitor.Wait(gate);
                        Interlocked.Decrement(ref blocked);
                    }
                    return;
                }
                spin.SpinOnce();
            }
        }
    }
}
