using System;
using System.Collections.Generic;

namespace HookeRope.Lab.Report
{
    /// <summary>Small statistics helpers for timings.</summary>
    public static class Stats
    {
        /// <summary>Median of the values (NaN when empty).</summary>
        public static double Median(IList<double> values)
        {
            if (values.Count == 0) return double.NaN;
            var copy = new double[values.Count];
            values.CopyTo(copy, 0);
            Array.Sort(copy);
            int mid = copy.Length / 2;
            return copy.Length % 2 == 1 ? copy[mid] : (copy[mid - 1] + copy[mid]) / 2;
        }

        /// <summary>Least-squares slope of log(y) against log(x): the scaling exponent.</summary>
        public static double LogLogSlope(IList<double> x, IList<double> y)
        {
            int n = x.Count;
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            for (int i = 0; i < n; i++)
            {
                double lx = Math.Log(x[i]), ly = Math.Log(y[i]);
                sx += lx;
                sy += ly;
                sxx += lx * lx;
                sxy += lx * ly;
            }
            double d = n * sxx - sx * sx;
            return d == 0 ? double.NaN : (n * sxy - sx * sy) / d;
        }
    }
}
