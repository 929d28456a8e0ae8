using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text.Json;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Scenarios
{
    /// <summary>
    /// Strict reader over one JSON object: every field read is marked; <see cref="RejectUnknown"/>
    /// then names any field nobody asked for. Every error names the JSON path.
    /// </summary>
    internal sealed class JsonFields
    {
        readonly JsonElement element;
        readonly HashSet<string> known = new HashSet<string>(StringComparer.Ordinal);

        /// <summary>JSON path of this object.</summary>
        public string Path { get; }

        public JsonFields(JsonElement element, string path)
        {
            if (element.ValueKind != JsonValueKind.Object)
                throw new ScenarioException(path, "expected an object, got " + Describe(element));
            this.element = element;
            Path = path;
            var seen = new HashSet<string>(StringComparer.Ordinal);
            foreach (var property in element.EnumerateObject())
                if (!seen.Add(property.Name))
                    throw new ScenarioException(Child(property.Name), "duplicate field");
        }

        public string Child(string name) => Path + "." + name;

        public bool Has(string name)
        {
            known.Add(name);
            return element.TryGetProperty(name, out var value) && value.ValueKind != JsonValueKind.Null;
        }

        JsonElement Get(string name)
        {
            known.Add(name);
            return element.GetProperty(name);
        }

        public void RejectUnknown()
        {
            foreach (var property in element.EnumerateObject())
                if (!known.Contains(property.Name))
                    throw new ScenarioException(Child(property.Name),
                        "unknown field (allowed: " + string.Join(", ", SortedKnown()) + ")");
        }

        List<string> SortedKnown()
        {
            var list = new List<string>(known);
            list.Sort(StringComparer.Ordinal);
            return list;
        }

        public JsonFields Object(string name)
        {
            return Has(name) ? new JsonFields(Get(name), Child(name)) : null;
        }

        public double Number(string name, double fallback, double min, double max, bool minExclusive = false, bool maxExclusive = false) =>
            OptionalNumber(name, min, max, minExclusive, maxExclusive) ?? fallback;

        public double? OptionalNumber(string name, double min, double max, bool minExclusive = false, bool maxExclusive = false)
        {
            if (!Has(name)) return null;
            return ReadNumber(Get(name), Child(name), min, max, minExclusive, maxExclusive);
        }

        /// <summary>The number of the table row's JSON field, range-checked against the row (its unit); <paramref name="fallback"/> when absent.</summary>
        public double Parameter(ParameterInfo row, double fallback) => Number(row.Json, fallback, row.Min, row.Max, row.MinExclusive, row.MaxExclusive);

        /// <summary>The row's number when given, else null (range-checked against the row).</summary>
        public double? OptionalParameter(ParameterInfo row) => OptionalNumber(row.Json, row.Min, row.Max, row.MinExclusive, row.MaxExclusive);

        /// <summary>The integer of the table row's JSON field, range-checked against the row; <paramref name="fallback"/> when absent.</summary>
        public int Parameter(ParameterInfo row, int fallback) => Integer(row.Json, fallback, (int)row.Min, (int)row.Max);

        /// <summary>The boolean of the table row's JSON field; <paramref name="fallback"/> when absent.</summary>
        public bool Parameter(ParameterInfo row, bool fallback) => Boolean(row.Json, fallback);

        public int Integer(string name, int fallback, int min, int max)
        {
            if (!Has(name)) return fallback;
            return ReadInteger(Get(name), Child(name), min, max);
        }

        public bool Boolean(string name, bool fallback)
        {
            if (!Has(name)) return fallback;
            var value = Get(name);
            if (value.ValueKind == JsonValueKind.True) return true;
            if (value.ValueKind == JsonValueKind.False) return false;
            throw new ScenarioException(Child(name), "expected true or false, got " + Describe(value));
        }

        public string String(string name, string fallback, int maxLength = 200)
        {
            if (!Has(name)) return fallback;
            var value = Get(name);
            if (value.ValueKind != JsonValueKind.String)
                throw new ScenarioException(Child(name), "expected a string, got " + Describe(value));
            string text = value.GetString();
            if (text.Length > maxLength)
                throw new ScenarioException(Child(name), $"too long ({text.Length} characters, at most {maxLength})");
            return text;
        }

        public string Choice(string name, string fallback, params string[] allowed)
        {
            string text = String(name, fallback);
            if (System.Array.IndexOf(allowed, text) < 0)
                throw new ScenarioException(Child(name), $"\"{text}\" is not one of: {string.Join(", ", allowed)}"
                    + Commands.Suggestions.DidYouMean(text, allowed));
            return text;
        }

        public Float3 Vector(string name, Float3 fallback, double limit = 1e6) => OptionalVector(name, limit) ?? fallback;

        public Float3? OptionalVector(string name, double limit = 1e6)
        {
            if (!Has(name)) return null;
            return ReadVector(Get(name), Child(name), limit);
        }

        public List<JsonElement> Array(string name, int maxCount)
        {
            var list = new List<JsonElement>();
            if (!Has(name)) return list;
            var value = Get(name);
            if (value.ValueKind != JsonValueKind.Array)
                throw new ScenarioException(Child(name), "expected an array, got " + Describe(value));
            int count = value.GetArrayLength();
            if (count > maxCount)
                throw new ScenarioException(Child(name), $"too many elements ({count}, at most {maxCount})");
            foreach (var item in value.EnumerateArray()) list.Add(item);
            return list;
        }

        public List<double> Numbers(string name, int maxCount, double min, double max)
        {
            var list = new List<double>();
            var items = Array(name, maxCount);
            for (int i = 0; i < items.Count; i++)
                list.Add(ReadNumber(items[i], $"{Child(name)}[{i}]", min, max, false));
            return list;
        }

        public static double ReadNumber(JsonElement value, string path, double min, double max, bool minExclusive, bool maxExclusive = false)
        {
            if (value.ValueKind != JsonValueKind.Number)
                throw new ScenarioException(path, "expected a number, got " + Describe(value));
            double number = value.GetDouble();
            bool tooLow = minExclusive ? number <= min : number < min;
            bool tooHigh = maxExclusive ? number >= max : number > max;
            if (!double.IsFinite(number) || tooLow || tooHigh)
                throw new ScenarioException(path, $"{Format(number)} is out of range {(minExclusive ? "(" : "[")}{Format(min)}, {Format(max)}{(maxExclusive ? ")" : "]")}");
            return number;
        }

        public static int ReadInteger(JsonElement value, string path, int min, int max)
        {
            if (value.ValueKind != JsonValueKind.Number)
                throw new ScenarioException(path, "expected an integer, got " + Describe(value));
            if (!value.TryGetInt64(out long number))
                throw new ScenarioException(path, $"expected an integer, got {value.GetRawText()}");
            if (number < min || number > max)
                throw new ScenarioException(path, $"{number} is out of range [{min}, {max}]");
            return (int)number;
        }

        public static Float3 ReadVector(JsonElement value, string path, double limit)
        {
            if (value.ValueKind != JsonValueKind.Array)
                throw new ScenarioException(path, "expected [x, y, z], got " + Describe(value));
            int count = value.GetArrayLength();
            if (count != 3)
                throw new ScenarioException(path, $"expected exactly 3 numbers [x, y, z], got {count} elements");
            var c = new float[3];
            int i = 0;
            foreach (var item in value.EnumerateArray())
            {
                c[i] = (float)ReadNumber(item, $"{path}[{i}]", -limit, limit, false);
                i++;
            }
            return new Float3(c[0], c[1], c[2]);
        }

        public static string Describe(JsonElement value)
        {
            switch (value.ValueKind)
            {
                case JsonValueKind.Object: return "an object";
                case JsonValueKind.Array: return "an array";
                case JsonValueKind.String: return "the string \"" + Truncate(value.GetString()) + "\"";
                case JsonValueKind.Number: return "the number " + value.GetRawText();
                case JsonValueKind.True: return "true";
                case JsonValueKind.False: return "false";
                default: return "null";
            }
        }

        static string Truncate(string text) => text.Length <= 40 ? text : text.Substring(0, 40) + "…";

        public static string Format(double value) => value.ToString("G6", CultureInfo.InvariantCulture);
    }
}
