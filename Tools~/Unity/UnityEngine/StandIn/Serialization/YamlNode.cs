using System.Collections.Generic;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: a node of Unity's YAML (scalar, mapping or sequence) with the line it starts on.</summary>
    internal abstract class YamlNode
    {
        protected YamlNode(int line) => Line = line;

        /// <summary>1-based line in the file.</summary>
        internal int Line { get; }
    }

    /// <summary>Not part of Unity: a YAML scalar (plain or quoted text).</summary>
    internal sealed class YamlScalar : YamlNode
    {
        internal YamlScalar(string value, bool quoted, int line) : base(line)
        {
            Value = value;
            Quoted = quoted;
        }

        /// <summary>The text, quotes and escapes resolved.</summary>
        internal string Value { get; }

        /// <summary>True when the text was quoted in the file.</summary>
        internal bool Quoted { get; }

        /// <inheritdoc/>
        public override string ToString() => Value;
    }

    /// <summary>Not part of Unity: a YAML mapping, entries in file order.</summary>
    internal sealed class YamlMapping : YamlNode
    {
        readonly List<YamlEntry> m_Entries = new List<YamlEntry>();

        internal YamlMapping(int line) : base(line) { }

        /// <summary>The entries in file order.</summary>
        internal IReadOnlyList<YamlEntry> Entries => m_Entries;

        internal void Add(YamlEntry entry) => m_Entries.Add(entry);

        /// <summary>The value of <paramref name="key"/>, or null.</summary>
        internal YamlNode Find(string key)
        {
            for (int i = 0; i < m_Entries.Count; i++)
                if (m_Entries[i].Key == key) return m_Entries[i].Value;
            return null;
        }
    }

    /// <summary>Not part of Unity: one "key: value" of a mapping, with the key's line.</summary>
    internal sealed class YamlEntry
    {
        internal YamlEntry(string key, YamlNode value, int line)
        {
            Key = key;
            Value = value;
            Line = line;
        }

        /// <summary>The key.</summary>
        internal string Key { get; }

        /// <summary>The value node.</summary>
        internal YamlNode Value { get; }

        /// <summary>1-based line of the key.</summary>
        internal int Line { get; }
    }

    /// <summary>Not part of Unity: a YAML sequence.</summary>
    internal sealed class YamlSequence : YamlNode
    {
        readonly List<YamlNode> m_Items = new List<YamlNode>();

        internal YamlSequence(int line) : base(line) { }

        /// <summary>The items in file order.</summary>
        internal IReadOnlyList<YamlNode> Items => m_Items;

        internal void Add(YamlNode item) => m_Items.Add(item);
    }
}
