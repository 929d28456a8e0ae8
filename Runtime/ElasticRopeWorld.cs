using System;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// The multi-rope world the <see cref="ElasticRope"/> components of the loaded scenes share in Play (issue 18
    /// item 4). With two or more ropes enabled, the first rope to run in a physics step copies every rope's
    /// attachment and collider poses in on the main thread, steps all of them at once on <see cref="WorkerCount"/>
    /// threads (<see cref="HookeRope.World.RopeWorld"/>: the same bits as each rope stepped alone, for any worker
    /// count) and copies forces, rig displacements and the break and stepped events out, again on the main thread.
    /// Each frame the first <see cref="RopeMeshRenderer"/> to run interpolates every drawn rope on the main thread,
    /// lets the world fill all tube meshes at once and uploads them. One rope alone keeps stepping and drawing inline,
    /// as without the world; edit mode never uses it. The world's threads are stopped when the last rope is
    /// disabled, on Application.quitting and, in the Editor, before a domain reload. Documentation~/index.md,
    /// "Many ropes".
    /// </summary>
    public static class ElasticRopeWorld
    {
        /// <summary>Largest <see cref="WorkerCount"/> (the world's limit).</summary>
        public const int MaxWorkerCount = 64;

        /// <summary>
        /// Threads per pass, the main thread included (1 … <see cref="MaxWorkerCount"/>; 1 = no extra thread). Default
        /// <see cref="DefaultWorkerCount"/>. A new value applies at the next pass (the world's threads are replaced
        /// between passes). Out of range → ArgumentOutOfRangeException.
        /// </summary>
        public static int WorkerCount
        {
            get => RopeWorldScheduler.WorkerCount;
            set
            {
                if (value < 1 || value > MaxWorkerCount)
                    throw new ArgumentOutOfRangeException(nameof(WorkerCount), value, "WorkerCount must be in [1, " + MaxWorkerCount + "] threads (the main thread included).");
                RopeWorldScheduler.WorkerCount = value;
            }
        }

        /// <summary>
        /// Logical processors (SystemInfo.processorCount) minus one, so one core stays free for Unity's render thread
        /// and job workers, between 1 and 8 (a pass wakes every worker, and more workers than ropes get nothing to
        /// do); on a 2-core machine that is 1: set <see cref="WorkerCount"/> to 2 to use both. Always 1 in WebGL
        /// players, which run no C# threads.
        /// </summary>
        public static int DefaultWorkerCount
        {
            get
            {
#if UNITY_WEBGL && !UNITY_EDITOR
                return 1;
#else
                return Math.Max(1, Math.Min(8, SystemInfo.processorCount - 1));
#endif
            }
        }

        /// <summary>Ropes enabled in Play and enrolled with the world (one alone steps inline).</summary>
        public static int RopeCount => RopeWorldScheduler.Count;

        /// <summary>True while the world steps the enrolled ropes: two or more of them.</summary>
        public static bool IsActive => RopeWorldScheduler.IsActive;
    }
}
