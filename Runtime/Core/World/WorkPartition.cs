using System;
using HookeRope.Solver;

namespace HookeRope.World
{
    /// <summary>
    /// Partition of the world's ropes into contiguous chunks of about equal estimated cost (the world makes
    /// <see cref="RopeWorld.ChunksPerWorker"/> per worker and the workers claim them as they become free):
    /// particles × substeps × iterations for the step plus the mesh vertices when meshes are filled (the count of the
    /// slot's last fill; before the first, one ring of sides + 1 per particle). It decides only
    /// which ropes go together; which thread steps a chunk depends on timing, and each rope is stepped by exactly one thread with the same code, so the results are
    /// the same bits whatever the partition and the worker count.
    /// </summary>
    internal static class WorkPartition
    {
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
        /// Writes chunk boundaries into <paramref name="bounds"/> (length chunks + 1): chunk w holds ropes
        /// [bounds[w], bounds[w + 1]). <paramref name="costs"/> holds one cost per rope (the first
        /// <paramref name="count"/> entries). Allocation-free.
        /// </summary>
        public static void Split(ReadOnlySpan<double> costs, int count, Span<int> bounds)
        {
            int chunks = bounds.Length - 1;
            double total = 0.0;
            for (int i = 0; i < count; i++) total += costs[i];
            bounds[0] = 0;
            int next = 0;
            double cumulative = 0.0;
            for (int w = 1; w < chunks; w++)
            {
                double target = total * w / chunks;
                // take ropes while the chunk's end stays closer to the target than the chunk without the rope
                while (next < count && cumulative + costs[next] * 0.5 <= target)
                {
                    cumulative += costs[next];
                    next++;
                }
                bounds[w] = next;
            }
            bounds[chunks] = count;
        }
    }
}
