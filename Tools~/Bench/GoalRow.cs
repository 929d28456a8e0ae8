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
        /// <summary>Median wall time of one 1/90 s frame (step + mesh fill of every rope), ms.</summary>
        public double MsPerFrame { get; set; }
        /// <summary>Fastest frame, ms (less sensitive to a loaded machine than the median).</summary>
        public double MinMsPerFrame { get; set; }
        /// <summary>Processor time of the whole process per frame (all threads, spinning included), ms: robust to other processes' load as long as this one's threads are not starved.</summary>
        public double CpuMsPerFrame { get; set; }
        /// <summary>Mean thread time of the ropes' steps per frame (RopeWorld.GetLastStepMilliseconds summed over the ropes, all workers), ms; 0 when not recorded.</summary>
        public double StepMsPerFrame { get; set; }
        /// <summary>Mean thread time of the ropes' mesh fills per frame (RopeWorld.GetLastFillMilliseconds summed over the ropes, all workers), ms; 0 when not recorded.</summary>
        public double MeshMsPerFrame { get; set; }
        /// <summary>Median ns per unit: per segment-substep (ropes × segments × substeps per frame), mesh included.</summary>
        public double NsPerUnit { get; set; }
        /// <summary>Instructions per unit from callgrind (all threads), or 0 when not measured.</summary>
        public double InstructionsPerUnit { get; set; }
        /// <summary>
        /// Mean tube-mesh vertices per rope over the measured frames (adaptive rings: the rope's shape sets it, and the
        /// lanyards dropped from straight need 1 … 6 rings per segment as the drop's waves pass), or 0 when not recorded.
        /// </summary>
        public double VerticesPerRope { get; set; }
        /// <summary>
        /// Frame of the drop the measurement ended at (the 20 warm-up frames included): rows that end at different frames
        /// draw different ring budgets, so compare the mesh columns only between rows that end near the same frame.
        /// </summary>
        public int LastFrame { get; set; }
        /// <summary>1-minute load average while measured.</summary>
        public double LoadAverage { get; set; }

        /// <summary>Work units per frame: ropes × segments × substeps.</summary>
        public double UnitsPerFrame => (double)Ropes * Segments * Substeps;
    }
}
