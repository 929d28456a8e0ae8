using System;
using System.Diagnostics;
using System.Threading;
using HookeRope.Solver;

namespace HookeRope.World
{
    /// <summary>
    /// Steps a set of independent <see cref="RopeSimulation"/>s on a fixed pool of worker threads (the calling thread
    /// is worker 0; <see cref="WorkerCount"/> − 1 long-lived background threads do the rest). Each pass splits the
    /// ropes into contiguous chunks of shrinking estimated cost (<see cref="WorkPartition.Split"/>: the first about
    /// 1/(4 W) of the pass, the last single ropes), which the workers claim in order as they become free (one
    /// compare-and-swap per chunk, tagged with the pass): a worker that the operating system wakes late (a loaded
    /// machine, a host's busy cores) takes fewer chunks instead of holding up the pass, the workers run out of work within
    /// about one rope of each other, and the pass ends when its last chunk is done, without waiting for a pool thread
    /// that was woken too late to take any, so a pass on W workers is never much slower than on one. Every rope is
    /// stepped by exactly one thread with the same code, so the results
    /// are the same bits for any worker count and any claiming order. Allocation-free per pass after
    /// warm-up (a slot's buffers are made at its first fill for the rope's ring budget, <see cref="RopeSimulation.GetVertexCapacity"/>,
    /// and again only after a break). An exception thrown by a rope is caught, the other
    /// ropes still finish the pass, and the caller gets an <see cref="InvalidOperationException"/> naming the lowest
    /// failing rope index with the rope's exception inside; the world stays usable. Ropes must not share state (a
    /// rope, its settings object, caller position arrays) and the host must not touch them while a pass runs. One
    /// caller thread at a time; <see cref="Dispose"/> joins the threads.
    /// </summary>
    public sealed class RopeWorld : IDisposable
    {
        private const int PhaseStep = 1, PhaseMesh = 2;

        private readonly WorkerPool pool;
        private readonly WakeSignal passDone = new WakeSignal();
        private int[] bounds = new int[5];
        private readonly Exception[] failure;
        private readonly int[] failureIndex;
        // per worker, one padded slot of WorkerTimingStride longs each (no two workers write one cache line):
        // [0] = timestamp of the worker's first claim in pass [2], [1] = timestamp it finished its last chunk of it
        private readonly long[] workerTimes;
        private long passStarted, passEnded;
        // the pass (high 32 bits) and its next unclaimed chunk (low 32 bits), claimed by compare-and-swap
        private long claim;
        private int generation;
        private int remainingChunks;
        private RopeSimulation[] ropes = new RopeSimulation[4];
        private RopeMeshSlot[] slots = new RopeMeshSlot[4];
        private StepReport[] reports = new StepReport[4];
        private double[] costs = new double[4];
        private long[] stepTicks = new long[4];
        private long[] fillTicks = new long[4];
        private int chunkCount;
        private bool[] failedInPass = new bool[4];
        private int count;
        private int phase;
        private float deltaTime;
        private bool running;

        /// <summary>
        /// Creates a world that runs every pass on <paramref name="workerCount"/> threads (1 … 64, the calling thread
        /// included; 1 = no extra thread). <see cref="DefaultWorkerCount"/> is one per logical processor.
        /// </summary>
        public RopeWorld(int workerCount = 1)
        {
            if (workerCount < 1 || workerCount > 64)
                throw new ArgumentOutOfRangeException(nameof(workerCount), workerCount, "workerCount must be in [1, 64].");
            failure = new Exception[workerCount];
            failureIndex = new int[workerCount];
            workerTimes = new long[(workerCount + 1) * WorkerTimingStride];
            pool = new WorkerPool(workerCount, Work, "HookeRope world worker");
        }

        /// <summary>One worker per logical processor (<see cref="Environment.ProcessorCount"/>), at most 64.</summary>
        public static int DefaultWorkerCount => Math.Max(1, Math.Min(64, Environment.ProcessorCount));

        /// <summary>Threads per pass, the calling thread included.</summary>
        public int WorkerCount => pool.WorkerCount;

        /// <summary>Ropes in the world.</summary>
        public int Count => count;

        /// <summary>True once <see cref="Dispose"/> has run.</summary>
        public bool IsDisposed => pool.IsDisposed;

        /// <summary>Called on each worker's thread with its index at the end of its share of every pass (tests measure per-thread allocation with it).</summary>
        internal Action<int> WorkerProbe { get; set; }

        /// <summary>Longs per worker in the timing array: 16 × 8 B = 128 B, two cache lines, so workers never share one.</summary>
        private const int WorkerTimingStride = 16;

        /// <summary>Wall-clock time (ms) of the last pass on the calling thread, hand-off and waiting included (0 before the first pass).</summary>
        internal double LastPassMilliseconds => (passEnded - passStarted) * 1000.0 / Stopwatch.Frequency;

        /// <summary>Chunks the last pass was split into (the workers claim them in order as they become free).</summary>
        internal int LastChunkCount => chunkCount;

        /// <summary>
        /// Time (ms) from the last pass's start until worker <paramref name="worker"/> claimed its first chunk of it (its
        /// wake-up; the partition for the calling thread), or the whole pass when it claimed none (woken too late).
        /// </summary>
        internal double LastWakeMilliseconds(int worker)
        {
            int at = (worker + 1) * WorkerTimingStride;
            long began = Volatile.Read(ref workerTimes[at + 2]) == generation ? workerTimes[at] : passEnded;
            return (began - passStarted) * 1000.0 / Stopwatch.Frequency;
        }

        /// <summary>
        /// Time (ms) of the last pass that worker <paramref name="worker"/> did not spend on its chunks: until its first
        /// claim and after its last chunk (pass − (end − first claim)); the whole pass when it claimed none.
        /// </summary>
        internal double LastIdleMilliseconds(int worker)
        {
            int at = (worker + 1) * WorkerTimingStride;
            long busy = Volatile.Read(ref workerTimes[at + 2]) == generation ? workerTimes[at + 1] - workerTimes[at] : 0;
            return (passEnded - passStarted - busy) * 1000.0 / Stopwatch.Frequency;
        }

        /// <summary>True while any worker thread is alive (false after <see cref="Dispose"/>).</summary>
        internal bool AnyWorkerAlive => pool.AnyThreadAlive;

        /// <summary>The rope at <paramref name="index"/> (0 … <see cref="Count"/> − 1, in the order added).</summary>
        public RopeSimulation GetRope(int index)
        {
            CheckIndex(index);
            return ropes[index];
        }

        /// <summary>The report of the rope's last step in this world (default before its first step).</summary>
        public StepReport GetLastReport(int index)
        {
            CheckIndex(index);
            return reports[index];
        }

        /// <summary>
        /// Wall-clock time (ms) the rope's last step in this world took on the thread that stepped it (0 before its
        /// first step): for a host that warns about slow ropes. Two timestamp reads per rope and pass.
        /// </summary>
        public double GetLastStepMilliseconds(int index)
        {
            CheckIndex(index);
            return stepTicks[index] * 1000.0 / Stopwatch.Frequency;
        }

        /// <summary>
        /// Wall-clock time (ms) the rope's last mesh fill in this world took on the thread that filled it (0 before its
        /// first fill, or when its mesh is off): with <see cref="GetLastStepMilliseconds"/>, the split of a pass between
        /// the step and the mesh. Two timestamp reads per rope and fill.
        /// </summary>
        public double GetLastFillMilliseconds(int index)
        {
            CheckIndex(index);
            return fillTicks[index] * 1000.0 / Stopwatch.Frequency;
        }

        /// <summary>
        /// True when the rope's step or mesh fill threw in the last pass (that pass's exception names only the lowest
        /// failing index; this flags every failing rope, so a host can leave their results alone).
        /// </summary>
        public bool LastPassFailed(int index)
        {
            CheckIndex(index);
            return failedInPass[index];
        }

        /// <summary>The rope's mesh slot, or null when its mesh is not filled by the world (<see cref="EnableMesh"/>).</summary>
        public RopeMeshSlot GetMeshSlot(int index)
        {
            CheckIndex(index);
            return slots[index];
        }

        /// <summary>
        /// Adds <paramref name="simulation"/> at the end and returns its index. Not during a pass; a rope can be in one
        /// world once. Allocates only when the world's arrays grow.
        /// </summary>
        public int Add(RopeSimulation simulation)
        {
            if (simulation == null) throw new ArgumentNullException(nameof(simulation));
            CheckIdle();
            if (IndexOf(simulation) >= 0) throw new ArgumentException("The rope is already in this world.", nameof(simulation));
            if (count == ropes.Length)
            {
                int capacity = ArrayGrowth.NextCapacity(count);
                Array.Resize(ref ropes, capacity);
                Array.Resize(ref slots, capacity);
                Array.Resize(ref reports, capacity);
                Array.Resize(ref costs, capacity);
                Array.Resize(ref stepTicks, capacity);
                Array.Resize(ref fillTicks, capacity);
                Array.Resize(ref failedInPass, capacity);
                Array.Resize(ref bounds, capacity + 1);
            }
            ropes[count] = simulation;
            slots[count] = null;
            reports[count] = default;
            stepTicks[count] = 0;
            fillTicks[count] = 0;
            failedInPass[count] = false;
            return count++;
        }

        /// <summary>
        /// Puts <paramref name="simulation"/> at <paramref name="index"/> in place of the rope there (a host that rebuilt
        /// its rope): same position in the order, same mesh slot (give the slot new caller arrays if the particle count
        /// changed), report and step time cleared. Not during a pass; a rope can be in one world once (replacing a
        /// rope by itself does nothing). Allocation-free.
        /// </summary>
        public void Replace(int index, RopeSimulation simulation)
        {
            if (simulation == null) throw new ArgumentNullException(nameof(simulation));
            CheckIndex(index);
            CheckIdle();
            int existing = IndexOf(simulation);
            if (existing == index) return;
            if (existing >= 0) throw new ArgumentException("The rope is already in this world (at index " + existing + ").", nameof(simulation));
            ropes[index] = simulation;
            reports[index] = default;
            stepTicks[index] = 0;
            fillTicks[index] = 0;
            failedInPass[index] = false;
        }

        /// <summary>Removes <paramref name="simulation"/> (the ropes after it move down one index); false when it is not in the world. Not during a pass.</summary>
        public bool Remove(RopeSimulation simulation)
        {
            CheckIdle();
            int index = IndexOf(simulation);
            if (index < 0) return false;
            int tail = count - index - 1;
            Array.Copy(ropes, index + 1, ropes, index, tail);
            Array.Copy(slots, index + 1, slots, index, tail);
            Array.Copy(reports, index + 1, reports, index, tail);
            Array.Copy(stepTicks, index + 1, stepTicks, index, tail);
            Array.Copy(fillTicks, index + 1, fillTicks, index, tail);
            Array.Copy(failedInPass, index + 1, failedInPass, index, tail);
            count--;
            ropes[count] = null;
            slots[count] = null;
            reports[count] = default;
            stepTicks[count] = 0;
            fillTicks[count] = 0;
            failedInPass[count] = false;
            return true;
        }

        /// <summary>Index of <paramref name="simulation"/> in the world, or −1.</summary>
        public int IndexOf(RopeSimulation simulation)
        {
            for (int i = 0; i < count; i++)
                if (ReferenceEquals(ropes[i], simulation)) return i;
            return -1;
        }

        /// <summary>Lets the world fill the tube mesh of the rope at <paramref name="index"/> in its mesh passes; returns the slot (the same one if already on).</summary>
        public RopeMeshSlot EnableMesh(int index)
        {
            CheckIndex(index);
            CheckIdle();
            return slots[index] ??= new RopeMeshSlot();
        }

        /// <summary>Stops filling the mesh of the rope at <paramref name="index"/> (its slot is dropped).</summary>
        public void DisableMesh(int index)
        {
            CheckIndex(index);
            CheckIdle();
            slots[index] = null;
            fillTicks[index] = 0;
        }

        /// <summary>Steps every rope by <paramref name="hostDeltaTime"/> seconds ((0, 1] s) in parallel (<see cref="RopeSimulation.Step"/>).</summary>
        public void Step(float hostDeltaTime) => RunPass(PhaseStep, hostDeltaTime);

        /// <summary>Fills the mesh slot of every rope that has an enabled one (<see cref="EnableMesh"/>, <see cref="RopeMeshSlot.Enabled"/>) in parallel, from the positions the slot names.</summary>
        public void FillMeshes() => RunPass(PhaseMesh, 0f);

        /// <summary>
        /// One pass that steps every rope by <paramref name="hostDeltaTime"/> seconds and then fills its mesh slot (if
        /// any) while the rope's data is still in the worker's cache: for hosts that draw the latest step.
        /// </summary>
        public void StepAndFillMeshes(float hostDeltaTime) => RunPass(PhaseStep | PhaseMesh, hostDeltaTime);

        /// <summary>Stops and joins the worker threads. The ropes are left as they are; a pass after this throws <see cref="ObjectDisposedException"/>. Idempotent.</summary>
        public void Dispose()
        {
            CheckIdle();
            if (pool.IsDisposed) return;
            pool.Dispose();
        }

        private void RunPass(int passPhase, float hostDeltaTime)
        {
            if (pool.IsDisposed) throw new ObjectDisposedException(nameof(RopeWorld));
            CheckIdle();
            if ((passPhase & PhaseStep) != 0 && !(hostDeltaTime > 0f && hostDeltaTime <= 1f))
                throw new ArgumentOutOfRangeException(nameof(hostDeltaTime), hostDeltaTime, "hostDeltaTime must be in (0, 1] s");
            passStarted = Stopwatch.GetTimestamp();
            phase = passPhase;
            deltaTime = hostDeltaTime;
            Partition(passPhase);
            remainingChunks = chunkCount;
            passDone.Reset();
            // publish the pass: everything above is written before a worker can claim one of its chunks
            generation++;
            Volatile.Write(ref claim, (long)generation << 32);
            running = true;
            try
            {
                pool.Wake();
                // the pass ends when its last chunk is done, whichever thread did it: a pool thread that wakes after
                // every chunk was claimed is not waited for (it finds the pass's chunks gone and goes back to sleep)
                passDone.Wait();
            }
            finally
            {
                passEnded = Stopwatch.GetTimestamp();
                running = false;
            }
            pool.RethrowEscaped();
            ThrowFirstFailure();
        }

        private void Partition(int passPhase)
        {
            int workers = pool.WorkerCount;
            if (workers == 1)
            {
                chunkCount = 1;
                bounds[0] = 0;
                bounds[1] = count;
                return;
            }
            bool step = (passPhase & PhaseStep) != 0;
            for (int i = 0; i < count; i++)
                costs[i] = WorkPartition.Cost(ropes[i], step, (passPhase & PhaseMesh) != 0 && slots[i] != null && slots[i].Enabled ? slots[i] : null);
            chunkCount = WorkPartition.Split(costs, count, workers, bounds);
        }

        private void Work(int worker)
        {
            int timing = (worker + 1) * WorkerTimingStride;
            int tagged = -1;
            // claim chunks in order until none is left (ropes within a chunk, and the chunks a worker takes, ascend); a
            // claim names its pass, so a thread woken for a pass that already ended claims nothing of the next one's
            // data unless that pass is running (then its chunks are as good as any)
            while (true)
            {
                long current = Volatile.Read(ref claim);
                int chunk = (int)(current & 0xffffffffL);
                if (chunk >= Volatile.Read(ref chunkCount)) break;
                if (Interlocked.CompareExchange(ref claim, current + 1, current) != current) continue;
                // claimed: the pass cannot end before this chunk is done, so its partition and phase are current
                int pass = (int)(current >> 32);
                if (pass != tagged)
                {
                    tagged = pass;
                    workerTimes[timing] = Stopwatch.GetTimestamp();
                    workerTimes[timing + 2] = pass;
                }
                bool step = (phase & PhaseStep) != 0, mesh = (phase & PhaseMesh) != 0;
                float dt = deltaTime;
                int end = bounds[chunk + 1];
                for (int i = bounds[chunk]; i < end; i++) Process(worker, i, step, mesh, dt);
                workerTimes[timing + 1] = Stopwatch.GetTimestamp();
                if (Interlocked.Decrement(ref remainingChunks) == 0) passDone.Set();
            }
            WorkerProbe?.Invoke(worker);
        }

        private void Process(int worker, int i, bool step, bool mesh, float dt)
        {
            failedInPass[i] = false;
            try
            {
                if (step)
                {
                    long started = Stopwatch.GetTimestamp();
                    reports[i] = ropes[i].Step(dt);
                    stepTicks[i] = Stopwatch.GetTimestamp() - started;
                }
                RopeMeshSlot slot = slots[i];
                if (mesh && slot != null && slot.Enabled)
                {
                    long started = Stopwatch.GetTimestamp();
                    slot.Fill(ropes[i]);
                    fillTicks[i] = Stopwatch.GetTimestamp() - started;
                }
            }
            catch (Exception e)
            {
                failedInPass[i] = true;
                if (failure[worker] != null) return;
                failure[worker] = e;
                failureIndex[worker] = i;
            }
        }

        private void ThrowFirstFailure()
        {
            int first = -1;
            for (int w = 0; w < failure.Length; w++)
                if (failure[w] != null && (first < 0 || failureIndex[w] < failureIndex[first])) first = w;
            if (first < 0) return;
            Exception e = failure[first];
            int index = failureIndex[first];
            Array.Clear(failure, 0, failure.Length);
            throw new InvalidOperationException("Rope " + index + " of the world failed during the pass (the other ropes finished it): " + e.Message, e);
        }

        private void CheckIndex(int index)
        {
            if ((uint)index >= (uint)count)
                throw new ArgumentOutOfRangeException(nameof(index), index, "index must be in [0, Count).");
        }

        private void CheckIdle()
        {
            if (Volatile.Read(ref running)) throw new InvalidOperationException("The world is running a pass; change it between passes, from the thread that runs them.");
        }
    }
}
