using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;

namespace HookeRope.Lab.Commands
{
    /// <summary>
    /// Progress for output that is not a terminal (a log file, a pipe, CI): a plain line every
    /// <see cref="IntervalSeconds"/> of wall time with the fraction done, the time spent and an ETA.
    /// </summary>
    public sealed class ProgressLines
    {
        /// <summary>Default wall time between two lines, s.</summary>
        public const double DefaultInterval = 10;

        readonly string label;
        readonly double total;
        readonly TextWriter writer;
        readonly Func<double> clock;
        double nextLine;

        /// <summary>Wall time between two lines, s.</summary>
        public double IntervalSeconds { get; }

        /// <summary>Lines for <paramref name="total"/> units of work named <paramref name="label"/>; <paramref name="clock"/> returns wall seconds (a stopwatch when null).</summary>
        public ProgressLines(string label, double total, TextWriter writer, double intervalSeconds = DefaultInterval, Func<double> clock = null)
        {
            this.label = label;
            this.total = Math.Max(total, 1);
            this.writer = writer;
            IntervalSeconds = intervalSeconds;
            if (clock == null)
            {
                var watch = Stopwatch.StartNew();
                clock = () => watch.Elapsed.TotalSeconds;
            }
            this.clock = clock;
            nextLine = intervalSeconds;
        }

        /// <summary>Reports <paramref name="done"/> units finished; writes a line when the interval has passed.</summary>
        public void Report(double done)
        {
            double now = clock();
            if (now < nextLine) return;
            nextLine = now + IntervalSeconds;
            writer.WriteLine(Line(label, done, total, now));
            writer.Flush();
        }

        /// <summary>"label: 45 % (450 of 1000), 4.2 s elapsed, about 5.1 s left".</summary>
        public static string Line(string label, double done, double total, double elapsed)
        {
            double fraction = Math.Clamp(done / Math.Max(total, 1), 0, 1);
            string left = fraction > 0 ? Duration(elapsed * (1 - fraction) / fraction) : "unknown";
            return string.Format(CultureInfo.InvariantCulture, "{0}: {1:0} % ({2:0} of {3:0}), {4} elapsed, about {5} left",
                label, fraction * 100, done, total, Duration(elapsed), left);
        }

        /// <summary>Seconds as "4.2 s", "3 min 05 s" or "1 h 02 min".</summary>
        public static string Duration(double seconds)
        {
            if (seconds < 60) return seconds.ToString("0.0", CultureInfo.InvariantCulture) + " s";
            long s = (long)Math.Round(seconds);
            if (s < 3600) return string.Format(CultureInfo.InvariantCulture, "{0} min {1:00} s", s / 60, s % 60);
            return string.Format(CultureInfo.InvariantCulture, "{0} h {1:00} min", s / 3600, s % 3600 / 60);
        }
    }
}
