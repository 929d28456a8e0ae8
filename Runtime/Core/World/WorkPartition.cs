using System;
using HookeRope.Solver;

namespace HookeRope.World
{
    /// <summary>
    /// Partition of the world's ropes into contiguous chunks that the workers claim in order as they become free:
    /// each chunk takes about 1/(<see cref="ChunkDivisor"/> · workers) of the estimated cost still left, so the chunks
    /// shrink from about 1/(4 W) of the pass to single ropes at its end (guided scheduling: few claims, and the workers
    /// run dry within about one rope of each other). The cost of a rope is particles × substeps × iterations for the
    /// step plus the mesh vertices when meshes are filled (the count of the slot's last fill; before the first, one ring
    /// of sides + 1 per particle). It decides only which ropes go together; which thread steps a chunk depends on
    /// timing, and each rope is stepped by exactly one thread with the same code, so the results are the same bits
    /// whatever the partition and the worker count.
    /// </summary>
    internal static class WorkPartition
    {
        /// <summary>A chunk takes 1/(ChunkDivisor · workers) of the cost left (4: the first chunk of 2 workers is 1/8 of the pass).</summary>
        public const int ChunkDivisor = 4;

        /// <summary>Estimated cost of one rope's pass (arbitrary units, ≥ 1); <paramref name="mesh"/> null = no mesh fill in this pass.</summary>
        public static double Cost(RopeSimulation simulation, bool step, RopeMeshSlot mesh)
        {
            Rope rope = simulation.Rope;
            double cost = 1.0;
            if (step) cost += (double)rope.ParticleCount * rope.Settings.Substeps * rope.Settings.Iterations;
            // a tube vertex costs roughly what a particle-substep costs (both a few tens of ns, Documentation~/solver.md)
            if (mesh != null)
            {
                int vertices = mesh.Update.VertexCount;
                cost += vertices > 0 ? vertices : (double)rope.ParticleCount * (simulation.MeshSettings.RadialSegments + 1);
            }
            return cost;
        }

        /// <summary>
        /// Writes chunk boundaries into <paramref name="bounds"/> (length ≥ <paramref name="count"/> + 1) and returns the
        /// number of chunks c (≥ 1; one empty chunk when there is no rope): chunk k holds ropes [bounds[k], bounds[k + 1]),
        /// every chunk but an empty world's holds at least one rope, bounds[0] = 0 and bounds[c] = count.
        /// <paramref name="costs"/> holds one cost (&gt; 0) per rope (the first <paramref name="count"/> entries). Allocation-free.
        /// </summary>
        public static int Split(ReadOnlySpan<double> costs, int count, int workers, Span<int> bounds)
        {
            bounds[0] = 0;
            if (count == 0)
            {
                bounds[1] = 0;
                return 1;
            }
            double left = 0.0;
            for (int i = 0; i < count; i++) left += costs[i];
            double share = 1.0 / (ChunkDivisor * Math.Max(1, workers));
            int chunks = 0, next = 0;
            while (next < count)
            {
                double target = left * share, taken = costs[next];
                next++;
                // take further ropes while the chunk's cost stays closer to the target than the chunk without the rope
                while (next < count && taken + costs[next] * 0.5 <= target)
                {
                    taken += costs[next];
                    next++;
                }
                left -= taken;
                bounds[++chunks] = next;
            }
            return chunks;
        }
    }
}
