using System;
using System.Threading;

namespace HookeRope.World
{
    /// <summary>
    /// A fixed set of long-lived worker threads that join passes of work: <see cref="Wake"/> sets one
    /// <see cref="WakeSignal"/> per pool thread, and each woken thread runs the work once with its worker
    /// index (1 … <see cref="WorkerCount"/> − 1); the caller runs worker 0 itself. The pool does not wait for its
    /// threads: the work decides what a late thread still finds to do (<see cref="RopeWorld"/> tags its chunks with the
    /// pass, so a thread woken after a pass ended finds nothing, or joins the next pass) and signals the pass's end
    /// itself, so a pass never waits for a thread that the operating system wakes late. With one worker no thread is
    /// created. Allocation-free per pass. An exception that escapes the work on a pool thread is kept and rethrown by the
    /// next <see cref="RethrowEscaped"/>. One caller at a time.
    /// </summary>
    internal sealed class WorkerPool : IDisposable
    {
        private readonly Action<int> work;
        private readonly Thread[] threads;
        private readonly WakeSignal[] start;
        private readonly Exception[] escaped;
        private volatile bool stopping;
        private bool disposed;

        /// <summary>
        /// Creates <paramref name="workerCount"/> − 1 background threads named "<paramref name="name"/> n" that wait for
        /// <see cref="Wake"/>. <paramref name="work"/> receives the worker index (0 … workerCount − 1).
        /// </summary>
        public WorkerPool(int workerCount, Action<int> work, string name)
        {
            if (workerCount < 1) throw new ArgumentOutOfRangeException(nameof(workerCount), workerCount, "workerCount must be at least 1.");
            this.work = work ?? throw new ArgumentNullException(nameof(work));
            WorkerCount = workerCount;
            escaped = new Exception[workerCount];
            threads = new Thread[workerCount - 1];
            start = new WakeSignal[workerCount - 1];
            for (int i = 0; i < threads.Length; i++)
            {
                start[i] = new WakeSignal();
                threads[i] = new Thread(Loop) { IsBackground = true, Name = name + " " + (i + 1) };
            }
            for (int i = 0; i < threads.Length; i++) threads[i].Start(i + 1);
        }

        /// <summary>Workers per pass, the calling thread included (≥ 1).</summary>
        public int WorkerCount { get; }

        /// <summary>True once <see cref="Dispose"/> has run.</summary>
        public bool IsDisposed => disposed;

        /// <summary>True while any pool thread is still alive (false after <see cref="Dispose"/>).</summary>
        public bool AnyThreadAlive
        {
            get
            {
                for (int i = 0; i < threads.Length; i++)
                    if (threads[i].IsAlive) return true;
                return false;
            }
        }

        /// <summary>
        /// Wakes every pool thread for one run of the work (a thread still inside an earlier run runs once more after
        /// it) and runs worker 0 on the calling thread; returns when worker 0's run returns.
        /// </summary>
        public void Wake()
        {
            if (disposed) throw new ObjectDisposedException(nameof(WorkerPool));
            for (int i = 0; i < start.Length; i++) start[i].Set();
            RunWorker(0);
        }

        /// <summary>Rethrows (wrapped) the exception that escaped the work on the lowest worker index since the last call, if any.</summary>
        public void RethrowEscaped()
        {
            for (int w = 0; w < escaped.Length; w++)
            {
                Exception e = Interlocked.Exchange(ref escaped[w], null);
                if (e == null) continue;
                for (int k = w + 1; k < escaped.Length; k++) Interlocked.Exchange(ref escaped[k], null);
                throw new InvalidOperationException("A world worker failed: " + e.Message, e);
            }
        }

        /// <summary>Stops and joins every pool thread (each finishes its current run first). Idempotent.</summary>
        public void Dispose()
        {
            if (disposed) return;
            disposed = true;
            stopping = true;
            for (int i = 0; i < start.Length; i++) start[i].Set();
            for (int i = 0; i < threads.Length; i++) threads[i].Join();
        }

        private void RunWorker(int worker)
        {
            try
            {
                work(worker);
            }
            catch (Exception e)
            {
                Interlocked.CompareExchange(ref escaped[worker], e, null);
            }
        }

        private void Loop(object state)
        {
            int worker = (int)state;
            WakeSignal go = start[worker - 1];
            while (true)
            {
                go.Wait();
                go.Reset();
                if (stopping) return;
                RunWorker(worker);
            }
        }
    }
}
