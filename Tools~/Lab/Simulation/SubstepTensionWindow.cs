using System;
using HookeRope.Solver;

namespace HookeRope.Lab.Simulation
{
    /// <summary>
    /// Largest and mean tension of the first and last segment over every substep of the host steps since the last CSV
    /// row (<see cref="Rope.PeakTensions"/>, <see cref="Rope.MeanTensions"/>), so a row misses no peak between rows.
    /// A broken end segment reads 0, as the end-of-step columns do.
    /// </summary>
    public sealed class SubstepTensionWindow
    {
        private double topMax, topSum, bottomMax, bottomSum;
        private int steps;

        /// <summary>Adds the substeps of the host step <paramref name="rope"/> just took.</summary>
        public void Add(Rope rope)
        {
            ReadOnlySpan<float> peak = rope.PeakTensions, mean = rope.MeanTensions;
            ReadOnlySpan<bool> broken = rope.BrokenSegments;
            int last = peak.Length - 1;
            if (last < 0) return;
            double top = broken[0] ? 0.0 : peak[0], bottom = broken[last] ? 0.0 : peak[last];
            topMax = steps == 0 ? top : Math.Max(topMax, top);
            bottomMax = steps == 0 ? bottom : Math.Max(bottomMax, bottom);
            topSum += broken[0] ? 0.0 : mean[0];
            bottomSum += broken[last] ? 0.0 : mean[last];
            steps++;
        }

        /// <summary>Writes the window into <paramref name="sample"/> (N; before any step: its end-of-step tensions) and starts a new one.</summary>
        public Sample Complete(Sample sample)
        {
            if (steps == 0)
            {
                sample.TopTensionMax = sample.TopTensionMean = sample.TopTension;
                sample.BottomTensionMax = sample.BottomTensionMean = sample.BottomTension;
            }
            else
            {
                sample.TopTensionMax = topMax;
                sample.TopTensionMean = topSum / steps;
                sample.BottomTensionMax = bottomMax;
                sample.BottomTensionMean = bottomSum / steps;
            }
            topMax = topSum = bottomMax = bottomSum = 0.0;
            steps = 0;
            return sample;
        }
    }
}
