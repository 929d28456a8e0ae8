namespace HookeRope.Bench
{
    /// <summary>One measured configuration of the goal table (a row of <c>goal</c>'s output and of the baseline file).</summary>
    public sealed class GoalRow
    {
        /// <summary>Row key, e.g. "goal 100x64 w2", "ropes 500x64 w2".</summary>
        public string Id { get; set; }
        /// <summary>Ropes in the world.</summary>
        public int Ropes { get; set; }
        /// <summary>Segments per rope.</summary>
        public int Segments { get; set; }
        /// <summary>Substeps per frame.</summary>
        public int Substeps { get; set; }
        /// <summary>Tube mesh sides (0 = no mesh).</summary>
        public int MeshSides { get; set; }
        /// <summary>Worker threads (caller included).</summary>
        public int Workers { get; set; }
        /// <summary>The meshes' TubeMeshSettings.RingTolerance (1 in the goal; a baseline saved before it existed reads 1).</summary>
        public float RingTolerance { get; set; } = 1f;
        /// <summary>
        /// The view-distance detail of <see cref="GoalScene.ApplyViewDetail"/>, m: 0 in the goal (every rope at
        /// <see cref="RingTolerance"/>); else each rope's tolerance follows its distance to <see cref="GoalScene.Viewer"/> every frame.
        /// </summary>
        public float DetailDistance { get; set; }
        /// <summary>Whether the meshes are filled with tangents (48-byte vertices, the goal; false: 32-byte <see cref="HookeRope.Geometry.LeanTubeVertex"/>; a baseline saved before it existed reads true).</summary>
        public bool Tangents { get; set; } = true;
        /// <summary>Frames of the scene every repeat measured, e.g. "45-74" (<see cref="GoalScene.Window"/>): rows compare only within one window.</summary>
        public string Window { get; set; }
        /// <summary>Freshly built worlds whose window was measured (each repeat times the same frames).</summary>
        public int Repeats { get; set; }
        /// <summary>Median wall time of one 1/90 s frame (step + mesh fill of every rope) over every measured frame of every repeat, ms.</summary>
        public double MsPerFrame { get; set; }
        /// <summary>Fastest frame, ms (less sensitive to a loaded machine than the median).</summary>
        public double MinMsPerFrame { get; set; }
        /// <summary>Mean frame of the fastest repeat (its window's wall time / frames), ms: the least disturbed run of the same frames.</summary>
        public double BestWindowMsPerFrame { get; set; }
        /// <summary>Processor time of the whole process per measured frame (all threads, spinning included; the windows only), ms: robust to other processes' load as long as this one's threads are not starved.</summary>
        public double CpuMsPerFrame { get; set; }
        /// <summary>Mean thread time of the ropes' steps per frame (RopeWorld.GetLastStepMilliseconds summed over the ropes, all workers), ms; 0 when not recorded.</summary>
        public double StepMsPerFrame { get; set; }
        /// <summary>Mean thread time of the ropes' mesh fills per frame (RopeWorld.GetLastFillMilliseconds summed over the ropes, all workers), ms; 0 when not recorded.</summary>
        public double MeshMsPerFrame { get; set; }
        /// <summary>
        /// Mean time per frame the workers spent not working on their share, summed over the workers, ms: the pool
        /// thread's wake-up plus every worker's wait after its last chunk (0 on one worker, give or take the partition).
        /// </summary>
        public double IdleMsPerFrame { get; set; }
        /// <summary>Mean time per frame from the pass's start until the last worker began (the pool thread's wake-up), ms.</summary>
        public double WakeMsPerFrame { get; set; }
        /// <summary>Median ns per unit: per segment-substep (ropes × segments × substeps per frame), mesh included.</summary>
        public double NsPerUnit { get; set; }
        /// <summary>
        /// Instructions per unit (segment-substep, mesh included) of the same window counted under callgrind on one
        /// worker (Tools~/Kernels/goal-count.sh, native code), or 0 when no count of this configuration is recorded.
        /// </summary>
        public double InstructionsPerUnit { get; set; }
        /// <summary>Instructions per frame (step + mesh of every rope, one worker) of the recorded count, or 0.</summary>
        public double InstructionsPerFrame { get; set; }
        /// <summary>Instructions of the step per segment-substep (the count without the mesh fills), or 0.</summary>
        public double StepInstructionsPerUnit { get; set; }
        /// <summary>Instructions of the mesh fills per tube vertex (count with meshes − count without), or 0.</summary>
        public double MeshInstructionsPerVertex { get; set; }
        /// <summary>What the instruction figures were counted with, e.g. "aot default 45-74" (compared only with the same), or null.</summary>
        public string InstructionSource { get; set; }
        /// <summary>
        /// Mean tube-mesh vertices per rope over the measured frames (adaptive rings: the rope's shape sets it; the
        /// window is where the lanyards' budget has settled, <see cref="GoalScene.WarmUpFrames"/>), or 0 when not recorded.
        /// </summary>
        public double VerticesPerRope { get; set; }
        /// <summary>The machine's floor under the mesh while measured: one core's best time to write one goal frame's vertex bytes (<see cref="MachineProbe.FillMilliseconds"/>), ms; 0 when not recorded.</summary>
        public double FillProbeMs { get; set; }
        /// <summary>The machine's dependent-load latency in 4 MiB while measured (<see cref="MachineProbe.ChaseNanoseconds"/>), ns; 0 when not recorded.</summary>
        public double ChaseProbeNs { get; set; }
        /// <summary>1-minute load average while measured.</summary>
        public double LoadAverage { get; set; }

        /// <summary>Work units per frame: ropes × segments × substeps.</summary>
        public double UnitsPerFrame => (double)Ropes * Segments * Substeps;
    }
}
