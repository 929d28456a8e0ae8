using System;
using System.Collections.Generic;

namespace HookeRope.Lab.Simulation
{
    /// <summary>
    /// Measurements of numerical damping on host-step series (sample k at time (k + 1)·dt): the amplitude of an
    /// oscillation over one period, the apexes of ballistic flights, and the contact time of a mass bouncing on a
    /// linear spring. The analytic answers they are compared with are in <see cref="PhysicsChecks"/>.
    /// </summary>
    public static class DissipationMeasures
    {
        /// <summary>
        /// Amplitude (the series' unit) at the middle of the window of samples with t in [start, start + period) s: the
        /// least-squares fit y ≈ c₀ + (c₁ + c₃·τ)·cos φ + (c₂ + c₄·τ)·sin φ, φ = 2π(t − start)/period, τ = t − the window's
        /// middle, gives sqrt(c₁² + c₂²). Exact for a sinusoid of that period whatever the sampling phase (a parabola
        /// through three samples of a 17.9-sample period reads up to 0.05 % off); the τ terms follow a changing amplitude,
        /// so the ratio of two windows a whole number of periods apart is the decay between them within 0.01 % of itself
        /// even at backward Euler's 13 % per period (without them the sampling phase moved it by up to 0.6 %). NaN when the
        /// window leaves the series or holds fewer than 8 samples.
        /// </summary>
        public static double WindowAmplitude(double[] y, double dt, double start, double period)
        {
            if (!(period > 0) || !(dt > 0) || !double.IsFinite(start) || start < 0) return double.NaN;
            double end = start + period, middle = start + period / 2;
            if (end > y.Length * dt + 1e-12) return double.NaN;
            double omega = 2 * Math.PI / period;
            var normal = new double[Basis, Basis];
            var rhs = new double[Basis];
            var f = new double[Basis];
            int count = 0;
            for (int k = Math.Max(0, (int)Math.Floor(start / dt) - 1); k < y.Length; k++)
            {
                double t = (k + 1) * dt;
                if (t < start - 1e-12) continue;
                if (t >= end - 1e-12) break;
                double phase = omega * (t - start), tau = t - middle, c = Math.Cos(phase), s = Math.Sin(phase);
                f[0] = 1; f[1] = c; f[2] = s; f[3] = tau * c; f[4] = tau * s;
                for (int i = 0; i < Basis; i++)
                {
                    rhs[i] += f[i] * y[k];
                    for (int j = 0; j < Basis; j++) normal[i, j] += f[i] * f[j];
                }
                count++;
            }
            if (count < 8) return double.NaN;
            var x = Solve(normal, rhs);
            return x == null ? double.NaN : Math.Sqrt(x[1] * x[1] + x[2] * x[2]);
        }

        /// <summary>Functions of the window fit: 1, cos, sin, τ·cos, τ·sin.</summary>
        const int Basis = 5;

        /// <summary>Solves a·x = b (a square, overwritten, as b) by Gaussian elimination with partial pivoting; null when singular.</summary>
        static double[] Solve(double[,] a, double[] b)
        {
            int n = b.Length;
            for (int col = 0; col < n; col++)
            {
                int pivot = col;
                for (int r = col + 1; r < n; r++) if (Math.Abs(a[r, col]) > Math.Abs(a[pivot, col])) pivot = r;
                if (!(Math.Abs(a[pivot, col]) > 0)) return null;
                if (pivot != col)
                {
                    for (int j = 0; j < n; j++) (a[col, j], a[pivot, j]) = (a[pivot, j], a[col, j]);
                    (b[col], b[pivot]) = (b[pivot], b[col]);
                }
                for (int r = col + 1; r < n; r++)
                {
                    double factor = a[r, col] / a[col, col];
                    for (int j = col; j < n; j++) a[r, j] -= factor * a[col, j];
                    b[r] -= factor * b[col];
                }
            }
            var x = new double[n];
            for (int r = n - 1; r >= 0; r--)
            {
                double sum = b[r];
                for (int j = r + 1; j < n; j++) sum -= a[r, j] * x[j];
                x[r] = sum / a[r, r];
            }
            return x;
        }

        /// <summary>
        /// The first <paramref name="count"/> apexes above the start of a drop series (drop along gravity, m; the load is
        /// above its start where the drop is negative): each local minimum below zero, refined as the vertex of the
        /// parabola through it and its two neighbours (exact for a free flight: every integrator moves a free particle on
        /// a parabola). Times in s, heights above the start in m; fewer entries when the run has fewer.
        /// </summary>
        public static List<(double Time, double Height)> Apexes(double[] drop, double dt, int count)
        {
            var list = new List<(double, double)>();
            for (int k = 1; k + 1 < drop.Length && list.Count < count; k++)
            {
                if (!(drop[k] < 0) || !(drop[k] < drop[k - 1]) || !(drop[k] <= drop[k + 1])) continue;
                double a = 0.5 * (drop[k - 1] + drop[k + 1]) - drop[k], b = 0.5 * (drop[k + 1] - drop[k - 1]);
                double s = a > 0 ? -b / (2 * a) : 0;
                list.Add(((k + 1 + s) * dt, -(drop[k] + b * s + a * s * s)));
            }
            return list;
        }

        /// <summary>
        /// Time (s) a mass <paramref name="mass"/> (kg) that reaches an unstretched massless spring of stiffness
        /// <paramref name="stiffness"/> (N/m) at <paramref name="speed"/> (m/s) under gravity <paramref name="g"/> (m/s²)
        /// stays on it: (π + 2·asin(x_s/A))/ω with ω = sqrt(k/M), x_s = Mg/k and A = sqrt(x_s² + v²/ω²).
        /// </summary>
        public static double ContactTime(double mass, double stiffness, double g, double speed)
        {
            double omega = Math.Sqrt(stiffness / mass), xs = mass * g / stiffness;
            double amplitude = Math.Sqrt(xs * xs + speed * speed / (omega * omega));
            return (Math.PI + 2 * Math.Asin(xs / amplitude)) / omega;
        }
    }
}
