using System;
using System.Collections.Generic;
using System.Globalization;

namespace HookeRope.Editor
{
    /// <summary>
    /// The rows of the inspector's Read-outs section for one or several selected ropes: a "Rope" row with the names, then
    /// elongation/strain, tensions, radii, break state, arrest force and its limits, permanent set and plastic work, absorber
    /// deployment, residual and step time, one value
    /// text per rope. A rope that is not built shows <see cref="NotBuilt"/> in every row. Pure logic (no GUI), so it is
    /// tested headless; ElasticRopeEditor draws it.
    /// </summary>
    internal static class RopeReadoutTable
    {
        /// <summary>The value text of a rope that has no simulation yet.</summary>
        public const string NotBuilt = "not built";

        /// <summary>Label of the first row, which holds the ropes' names.</summary>
        public const string NameLabel = "Rope";

        static readonly (string Label, Func<ElasticRope, string> Text)[] s_Rows =
        {
            ("Elongation / strain", r => Format(r.Elongation, "m") + " / " + Format(r.Strain, "")),
            ("Top / bottom tension", r => Format(r.TopTension, "N") + " / " + Format(r.BottomTension, "N")),
            ("Peak tension", r => Format(r.PeakTension, "N")),
            ("Min radius / neck radius", r => Format(r.MinRadius, "m") + " / " + Format(r.NeckRadius, "m")),
            ("Broken", r => r.IsBroken ? "yes" : "no"),
            ("Arrest force (peak)", r => Format(r.ArrestForce, "N") + " (" + Format(r.PeakArrestForce, "N") + ")"),
            ("EN 355 (6 kN)", r => r.MeetsEn355 ? "within limit" : "EXCEEDED"),
            ("ANSI Z359.13 (8 kN)", r => r.MeetsAnsiZ359_13 ? "within limit" : "EXCEEDED"),
            ("Permanent set / plastic work", r => Format(r.PlasticElongation, "m") + " / " + Format(r.PlasticWork, "J")),
            ("Absorber deployed", r => r.EnergyAbsorber ? Format(r.AbsorberDeployed, "m") + " of " + Format(r.AbsorberDeployment, "m") : "no absorber"),
            ("Residual (strain error)", r => Format(r.Residual, "")),
            ("Step time", r => Format(r.StepMilliseconds, "ms")),
        };

        /// <summary>Number of rows <see cref="Build"/> returns: the name row and the 12 read-out rows.</summary>
        public static int RowCount => s_Rows.Length + 1;

        /// <summary>The rows for <paramref name="ropes"/> (selection order; null entries, e.g. destroyed targets, are skipped).</summary>
        public static IReadOnlyList<ReadoutRow> Build(IReadOnlyList<ElasticRope> ropes)
        {
            if (ropes == null) throw new ArgumentNullException(nameof(ropes));
            var live = new List<ElasticRope>(ropes.Count);
            foreach (var rope in ropes)
                if (rope != null) live.Add(rope);

            var rows = new List<ReadoutRow>(RowCount);
            var names = new string[live.Count];
            for (int i = 0; i < live.Count; i++) names[i] = live[i].name;
            rows.Add(new ReadoutRow(NameLabel, names));
            foreach (var (label, text) in s_Rows)
            {
                var values = new string[live.Count];
                for (int i = 0; i < live.Count; i++) values[i] = live[i].IsBuilt ? text(live[i]) : NotBuilt;
                rows.Add(new ReadoutRow(label, values));
            }
            return rows;
        }

        /// <summary><paramref name="value"/> with 4 significant digits (invariant culture) and a space and <paramref name="unit"/> when it has one.</summary>
        public static string Format(float value, string unit) =>
            value.ToString("G4", CultureInfo.InvariantCulture) + (unit.Length > 0 ? " " + unit : "");
    }
}
