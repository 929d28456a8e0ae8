using System;
using System.Threading;
using HookeRope.World;
using NUnit.Framework;

namespace HookeRope.Tests.Core.World
{
    /// <summary>The world's hand-off signal: a wait that really blocks allocates nothing, even the first one of a thread, and every blocked waiter wakes.</summary>
    public sealed class WakeSignalTests
    {
        /// <summary>Bytes allocated on a fresh thread by its first wait that blocks (until another thread sets the signal), and whether it returned.</summary>
        private static (long Bytes, bool Returned) FirstBlockingWait(WakeSignal signal)
        {
            long bytes = -1;
            bool returned = false;
            using var blocking = new ManualResetEventSlim(false);
            var waiter = new Thread(() =>
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                blocking.Set();
                signal.Wait();
                bytes = GC.GetAllocatedBytesForCurrentThread() - before;
                returned = true;
            });
            waiter.Start();
            blocking.Wait();
            // the waiter's spin takes microseconds; on a loaded machine it may be scheduled late, so wait (up to 5 s) until it
            // is blocked on the signal's lock (nothing else in its wait sleeps or blocks)
            bool blocked = SpinWait.SpinUntil(() => (waiter.ThreadState & ThreadState.WaitSleepJoin) != 0, 5000);
            Assert.That(blocked, Is.True, "the waiter is blocked");
            signal.Set();
            Assert.That(waiter.Join(5000), Is.True, "the waiter woke");
            return (bytes, returned);
        }

        [Test]
        public void AWaitThatBlocksAllocatesNothingTheFirstTime()
        {
            var signal = new WakeSignal();
            (long bytes, bool returned) = FirstBlockingWait(signal);
            Assert.That(returned, Is.True);
            Assert.That(signal.IsSet, Is.True);
            // ManualResetEventSlim allocates its 24-byte lock object here
            Assert.That(bytes, Is.EqualTo(0), "bytes allocated by the first blocking wait");
        }

        /// <summary>Bytes allocated on this thread by <paramref name="count"/> waits on <paramref name="signal"/>.</summary>
        private static long BytesOfWaits(WakeSignal signal, int count)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < count; i++) signal.Wait();
            return GC.GetAllocatedBytesForCurrentThread() - before;
        }

        [Test]
        public void ASetSignalReturnsAtOnceUntilReset()
        {
            var signal = new WakeSignal();
            signal.Set();
            Assert.That(BytesOfWaits(signal, 1000), Is.EqualTo(0), "bytes allocated by 1000 waits on a set signal");
            signal.Reset();
            Assert.That(signal.IsSet, Is.False);
            (long bytes, bool returned) = FirstBlockingWait(signal);
            Assert.That(returned && bytes == 0, Is.True, "blocked again after the reset, woke on the next set, nothing allocated");
        }

        [Test]
        public void EveryBlockedWaiterWakesOnOneSet()
        {
            var signal = new WakeSignal();
            var waiters = new Thread[3];
            int woke = 0;
            for (int i = 0; i < waiters.Length; i++)
            {
                waiters[i] = new Thread(() => { signal.Wait(); Interlocked.Increment(ref woke); });
                waiters[i].Start();
            }
            Thread.Sleep(50);
            Assert.That(Volatile.Read(ref woke), Is.EqualTo(0), "no waiter passes an unset signal");
            signal.Set();
            foreach (var t in waiters) Assert.That(t.Join(5000), Is.True);
            Assert.That(woke, Is.EqualTo(waiters.Length));
        }

        [Test]
        public void ASetRacingTheWaitersIsNeverLost()
        {
            // many short hand-offs between two threads, each wait racing its set: a lost wake-up hangs the ping-pong
            var ping = new WakeSignal();
            var pong = new WakeSignal();
            const int rounds = 2000;
            var other = new Thread(() =>
            {
                for (int i = 0; i < rounds; i++)
                {
                    ping.Wait();
                    ping.Reset();
                    pong.Set();
                }
            });
            other.Start();
            for (int i = 0; i < rounds; i++)
            {
                ping.Set();
                pong.Wait();
                pong.Reset();
            }
            Assert.That(other.Join(5000), Is.True, "both threads finished " + rounds + " hand-offs");
        }
    }
}
