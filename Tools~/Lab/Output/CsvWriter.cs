using System.Globalization;
using System.IO;
using System.Text;
using HookeRope.Lab.Simulation;

namespace HookeRope.Lab.Output
{
    /// <summary>Writes a run's time series as CSV (invariant culture, full precision, no "-0", SI units in the header).</summary>
    public static class CsvWriter
    {
        /// <summary>Header line: one column per <see cref="Sample"/> field, unit as suffix.</summary>
        public const string Header =
            "time_s,load_x_m,load_y_m,load_z_m,load_vx_mps,load_vy_mps,load_vz_mps," +
            "top_tension_N,bottom_tension_N,elongation_m,min_radius_m,neck_radius_m,broken,residual,energy_J," +
            "top_tension_max_N,top_tension_mean_N,bottom_tension_max_N,bottom_tension_mean_N";

        /// <summary>Writes <paramref name="result"/> to <paramref name="path"/>.</summary>
        public static void Write(RunResult result, string path)
        {
            using (var writer = new StreamWriter(path, false, new UTF8Encoding(false)))
                Write(result, writer);
        }

        /// <summary>Writes <paramref name="result"/> to a text writer.</summary>
        public static void Write(RunResult result, TextWriter writer)
        {
            writer.WriteLine(Header);
            var line = new StringBuilder(256);
            foreach (var s in result.Samples)
            {
                line.Clear();
                foreach (double value in new[]
                {
                    s.Time, s.X, s.Y, s.Z, s.VX, s.VY, s.VZ,
                    s.TopTension, s.BottomTension, s.Elongation, s.MinRadius, s.NeckRadius,
                })
                    Append(line, value).Append(',');
                line.Append(s.Broken ? '1' : '0').Append(',');
                Append(line, s.Residual).Append(',');
                Append(line, s.Energy);
                foreach (double value in new[] { s.TopTensionMax, s.TopTensionMean, s.BottomTensionMax, s.BottomTensionMean })
                    Append(line.Append(','), value);
                writer.WriteLine(line.ToString());
            }
        }

        /// <summary>Header of the radius-profile CSV (long format: one row per instant and point along the rope).</summary>
        public const string RadiusHeader = "time_s,moment,arc_m,radius_m";

        /// <summary>Writes the radius profiles of <paramref name="result"/> (outputs.profileTimes, "requested", and the key moments: neck onset, thinnest (intact), break) to <paramref name="path"/>.</summary>
        public static void WriteRadiusProfiles(RunResult result, string path)
        {
            using (var writer = new StreamWriter(path, false, new UTF8Encoding(false)))
            {
                writer.WriteLine(RadiusHeader);
                var line = new StringBuilder(64);
                var all = new System.Collections.Generic.List<RadiusProfile>(result.KeyProfiles);
                all.AddRange(result.Profiles);
                all.Sort((a, b) => a.Time.CompareTo(b.Time));
                foreach (var profile in all)
                    for (int i = 0; i < profile.Radius.Length; i++)
                    {
                        line.Clear();
                        Append(line, profile.Time).Append(',');
                        line.Append(profile.Label.Length > 0 ? profile.Label : "requested").Append(',');
                        Append(line, profile.Arc[i]).Append(',');
                        Append(line, profile.Radius[i]);
                        writer.WriteLine(line.ToString());
                    }
            }
        }

        /// <summary>Appends <paramref name="value"/> at full precision (shortest round-trip form, invariant culture); −0 is written as 0.</summary>
        public static StringBuilder Append(StringBuilder line, double value) =>
            line.Append(Format(value));

        /// <summary><paramref name="value"/> at full precision (shortest text that reads back to the same double); −0 becomes "0".</summary>
        public static string Format(double value) => (value == 0 ? 0.0 : value).ToString("R", CultureInfo.InvariantCulture);
    }
}
