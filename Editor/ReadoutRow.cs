using System.Collections.Generic;

namespace HookeRope.Editor
{
    /// <summary>One line of the inspector's Read-outs section: a label and one value text per selected rope, in selection order.</summary>
    internal sealed class ReadoutRow
    {
        /// <summary>Creates a row.</summary>
        public ReadoutRow(string label, IReadOnlyList<string> values)
        {
            Label = label;
            Values = values;
        }

        /// <summary>What the row shows, with its unit in the value texts (e.g. "Peak tension").</summary>
        public string Label { get; }

        /// <summary>The value text of each rope (numbers with 4 significant digits and their SI unit).</summary>
        public IReadOnlyList<string> Values { get; }

        /// <summary>The values as one table cell line, separated by " | " (how several ropes are shown side by side).</summary>
        public string Joined => string.Join(" | ", Values);
    }
}
