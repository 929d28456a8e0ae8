using UnityEngine;

namespace HookeRope
{
    // The shared multi-rope world (issue 18 item 4): an enabled rope in Play is enrolled with RopeWorldScheduler, which
    // steps every enrolled rope on worker threads once two or more are enrolled. Documentation~/solver.md, "Many ropes".
    public sealed partial class ElasticRope
    {
        bool _enabledInPlay;

        /// <summary>
        /// True while this rope is stepped by the shared multi-rope world (two or more ropes enabled in Play, stepped
        /// in FixedUpdate or Update mode); false when it steps alone, inline, in its own FixedUpdate or Update.
        /// </summary>
        public bool IsSteppedInWorld => WorldIndex >= 0 && ElasticRopeWorld.IsActive;

        /// <summary>Index of this rope in the scheduler's list and in the world (−1: not enrolled).</summary>
        internal int WorldIndex { get; set; } = -1;

        /// <summary>The physics step this rope last stepped in (the scheduler's key; NaN before the first).</summary>
        internal double SteppedKey { get; set; } = double.NaN;

        /// <summary>The enabled renderer drawing this rope (set by <see cref="RopeMeshRenderer"/> while it is enabled), or null.</summary>
        internal RopeMeshRenderer Drawer { get; set; }

        /// <summary>True between OnEnable and OnDisable in Play: the rope belongs in the world once it is built.</summary>
        internal bool WantsWorld => _enabledInPlay;

        void OnEnable()
        {
            if (!Application.isPlaying) return;
            _enabledInPlay = true;
            RopeWorldScheduler.Enroll(this);
        }

        void OnDisable()
        {
            _enabledInPlay = false;
            RopeWorldScheduler.Withdraw(this);
        }
    }
}
