using System;
using System.Threading;

namespace HookeRope.World
{
    /// <summary>
    /// A fixed set of long-lived worker threads that run one pass of work together: <see cref="Run"/> hands worker
    /// indices 1 … <see cref="WorkerCount"/> − 1 to the pool threads (one <see cref="ManualResetEventSlim"/> each), runs
    /// worker 0 on the calling thread and returns when every worker has finished (a countdown that the last worker
    /// turns into one <see cref="ManualResetEventSlim"/>). With one worker no thread is created. Allocation-free per
    /// pass. An exception that escapes the work of a worker is rethrown on the caller (the lowest worker index wins).
    /// One caller at a time; not re-entrant.
    /// </summary>
    internal sealed class WorkerPool : IDisposable
    {
        private readonly Action<int> work;
        private readonly Thread[] threads;
        private readonly ManualResetEventSlim[] start;
        private readonly ManualResetEventSlim finished;
        private readonly Exception[] escaped;
        private int pending;
        private volatile bool stopping;
        private bool disposed;

        /// <summary>
        /// Creates <paramref name="workerCount"/> − 1 background threads named "<paramref name="name"/> n" that wait for
        /// <see cref="Run"/>. <paramref name="work"/> receives the worker index (0 … workerCount − 1).
        /// </summary>
        public WorkerPool(int workerCount, Action<int> work, string name)
        {
            if (workerCount < 1) throw new ArgumentOutOfRangeException(nameof(workerCount), workerCount, "workerCount must be at least 1.");
            this.work = work ?? throw new ArgumentNullException(nameof(work));
            WorkerCount = workerCount;
            escaped = new Exception[workerCount];
            threads = new Thread[workerCount - 1];
            start = new ManualResetEventSlim[workerCount - 1];
            finished = new ManualResetEventSlim(false);
            for (int i = 0; i < threads.Length; i++)
            {
                start[i] = new ManualResetEventSlim(false);
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

        /// <summary>Runs the work once on every worker and waits for all of them; rethrows an escaped exception.</summary>
        public void Run()
        {
            if (disposed) throw new ObjectDisposedException(nameof(WorkerPool));
            if (threads.Length > 0)
            {
                finished.Reset();
                Volatile.Write(ref pending, threads.Length);
                for (int i = 0; i < start.Length; i++) start[i].Set();
            }
            RunWorker(0);
            if (threads.Length > 0) finished.Wait();
            for (int w = 0; w < escaped.Length; w++)
            {
                Exception e = escaped[w];
                if (e == null) continue;
                for (int k = w; k < escaped.Length; k++) escaped[k] = null;
                throw new InvalidOperationException("A world worker failed: " + e.Message, e);
            }
        }

        /// <summary>Stops and joins every pool thread (each finishes its current pass first) and releases the events. Idempotent.</summary>
        public void Dispose()
        {
            if (disposed) return;
            disposed = true;
            stopping = true;
            for (int i = 0; i < start.Length; i++) start[i].Set();
            for (int i = 0; i < threads.Length; i++) threads[i].Join();
            for (int i = 0; i < start.Length; i++) start[i].Dispose();
            finished.Dispose();
        }

        private void RunWorker(int worker)
        {
            try
            {
                work(worker);
            }
            catch (Exception e)
            {
                escaped[worker] = e;
            }
        }

        private void Loop(object state)
        {
            int worker = (int)state;
            ManualResetEventSlim go = start[worker - 1];
            while (true)
            {
                go.Wait();
                go.Reset();
                if (stopping) return;
                RunWorker(worker);
                if (Interlocked.Decrement(ref pending) == 0) finished.Set();
            }
        }
    }
}
