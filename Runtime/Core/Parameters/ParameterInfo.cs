using System;
using System.Collections.Generic;

namespace HookeRope
{
    /// <summary>
    /// One row of <see cref="RopeParameters"/>: a user-facing parameter with its name, label, unit, valid range,
    /// default, tooltip and lab JSON name. Ranges and defaults are in the row's <see cref="Unit"/> (SI).
    /// </summary>
    public sealed class ParameterInfo
    {
        internal ParameterInfo(string name, string label, string unit, ParameterGroup group, ParameterKind kind,
            double min, double max, double defaultValue, string tooltip, string json, bool inInspector,
            bool minExclusive = false, bool allowsPositiveInfinity = false, float[] defaultComponents = null, bool maxExclusive = false)
        {
            Name = name;
            Label = label;
            Unit = unit;
            Group = group;
            Kind = kind;
            Min = min;
            Max = max;
            Default = defaultValue;
            Tooltip = tooltip;
            Json = json;
            InInspector = inInspector;
            MinExclusive = minExclusive;
            MaxExclusive = maxExclusive;
            AllowsPositiveInfinity = allowsPositiveInfinity;
            DefaultComponents = defaultComponents ?? Array.Empty<float>();
        }

        /// <summary>The property name (PascalCase), the same on the component and the core settings classes.</summary>
        public string Name { get; }

        /// <summary>The human-readable label used in inspector messages, e.g. "Rest length".</summary>
        public string Label { get; }

        /// <summary>The SI unit of Min, Max and Default, e.g. "m" or "Pa"; empty for dimensionless values.</summary>
        public string Unit { get; }

        /// <summary>The settings group the parameter belongs to.</summary>
        public ParameterGroup Group { get; }

        /// <summary>The value type.</summary>
        public ParameterKind Kind { get; }

        /// <summary>Lower bound in <see cref="Unit"/> (exclusive when <see cref="MinExclusive"/>); per component for vectors and colours.</summary>
        public double Min { get; }

        /// <summary>Upper bound in <see cref="Unit"/> (exclusive when <see cref="MaxExclusive"/>); per component for vectors and colours.</summary>
        public double Max { get; }

        /// <summary>Default value in <see cref="Unit"/> (the component and prefab value); NaN for vectors and colours.</summary>
        public double Default { get; }

        /// <summary>The components of the default of a vector (x, y, z) or colour (r, g, b, a) row; empty otherwise.</summary>
        public IReadOnlyList<float> DefaultComponents { get; }

        /// <summary>The inspector tooltip text.</summary>
        public string Tooltip { get; }

        /// <summary>The field name in lab scenario JSON, or null when the lab has no such field.</summary>
        public string Json { get; }

        /// <summary>True when the component or renderer has an inspector field m_&lt;Name&gt; for it.</summary>
        public bool InInspector { get; }

        /// <summary>True when <see cref="Min"/> itself is not allowed (the range is (Min, Max]).</summary>
        public bool MinExclusive { get; }

        /// <summary>True when <see cref="Max"/> itself is not allowed (the range is [Min, Max) or (Min, Max)).</summary>
        public bool MaxExclusive { get; }

        /// <summary>True when +∞ is accepted by <see cref="RopeParameters.Check(float, ParameterInfo)"/> (inextensible); the inspector range stays finite.</summary>
        public bool AllowsPositiveInfinity { get; }

        /// <summary>The range as text, e.g. "[0.01, 10000] m", "(0, 1] m" or "(0, 1)".</summary>
        public string RangeText => RopeParameters.FormatRange(this);

        /// <inheritdoc />
        public override string ToString() => Name + " " + RangeText;
    }
}
