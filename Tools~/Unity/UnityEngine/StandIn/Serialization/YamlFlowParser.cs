namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: parses YAML flow collections as Unity writes them on one line ({fileID: 0},
    /// {x: 0, y: -9.81, z: 0}, [], [a, b]), with plain or quoted scalars.
    /// </summary>
    internal sealed class YamlFlowParser
    {
        readonly string m_Text;
        readonly string m_File;
        readonly int m_Line;
        int m_Pos;

        YamlFlowParser(string text, string file, int line)
        {
            m_Text = text;
            m_File = file;
            m_Line = line;
        }

        /// <summary>Parses <paramref name="text"/> (one flow value, nothing after it).</summary>
        internal static YamlNode Parse(string text, string file, int line)
        {
            var parser = new YamlFlowParser(text, file, line);
            var node = parser.Value();
            parser.SkipSpace();
            if (parser.m_Pos != text.Length) throw parser.Error("unexpected '" + text.Substring(parser.m_Pos) + "' after a flow value");
            return node;
        }

        /// <summary>True when the brackets and quotes of <paramref name="text"/> are closed.</summary>
        internal static bool IsComplete(string text)
        {
            int depth = 0;
            char quote = '\0';
            for (int i = 0; i < text.Length; i++)
            {
                char c = text[i];
                if (quote != '\0')
                {
                    if (c == '\\' && quote == '"') { i++; continue; }
                    if (c == quote) quote = '\0';
                    continue;
                }
                if (c == '\'' || c == '"') quote = c;
                else if (c == '{' || c == '[') depth++;
                else if (c == '}' || c == ']') depth--;
            }
            return depth <= 0 && quote == '\0';
        }

        YamlNode Value()
        {
            SkipSpace();
            if (m_Pos >= m_Text.Length) return new YamlScalar("", false, m_Line);
            char c = m_Text[m_Pos];
            if (c == '{') return Mapping();
            if (c == '[') return Sequence();
            if (c == '\'' || c == '"') return Quoted();
            return new YamlScalar(Plain(isKey: false), false, m_Line);
        }

        YamlMapping Mapping()
        {
            var map = new YamlMapping(m_Line);
            m_Pos++;
            SkipSpace();
            if (Peek() == '}') { m_Pos++; return map; }
            while (true)
            {
                SkipSpace();
                string key = Peek() == '\'' || Peek() == '"' ? ((YamlScalar)Quoted()).Value : Plain(isKey: true);
                SkipSpace();
                if (Peek() != ':') throw Error("expected ':' after key '" + key + "'");
                m_Pos++;
                var value = Value();
                map.Add(new YamlEntry(key, value, m_Line));
                SkipSpace();
                char next = Peek();
                m_Pos++;
                if (next == '}') return map;
                if (next != ',') throw Error("expected ',' or '}' in a flow mapping");
            }
        }

        YamlSequence Sequence()
        {
            var seq = new YamlSequence(m_Line);
            m_Pos++;
            SkipSpace();
            if (Peek() == ']') { m_Pos++; return seq; }
            while (true)
            {
                seq.Add(Value());
                SkipSpace();
                char next = Peek();
                m_Pos++;
                if (next == ']') return seq;
                if (next != ',') throw Error("expected ',' or ']' in a flow sequence");
            }
        }

        YamlScalar Quoted()
        {
            char quote = m_Text[m_Pos];
            int start = ++m_Pos;
            while (m_Pos < m_Text.Length)
            {
                char c = m_Text[m_Pos];
                if (quote == '"' && c == '\\') { m_Pos += 2; continue; }
                if (c == quote)
                {
                    if (quote == '\'' && m_Pos + 1 < m_Text.Length && m_Text[m_Pos + 1] == '\'') { m_Pos += 2; continue; }
                    string inner = m_Text.Substring(start, m_Pos - start);
                    m_Pos++;
                    string value = quote == '\'' ? YamlScalarText.SingleQuoted(inner) : YamlScalarText.DoubleQuoted(inner);
                    if (value == null) throw Error("malformed escape in \"" + inner + "\"");
                    return new YamlScalar(value, true, m_Line);
                }
                m_Pos++;
            }
            throw Error("unterminated quoted scalar");
        }

        string Plain(bool isKey)
        {
            int start = m_Pos;
            while (m_Pos < m_Text.Length)
            {
                char c = m_Text[m_Pos];
                if (c == ',' || c == '}' || c == ']' || c == '{' || c == '[') break;
                if (c == ':' && (isKey || m_Pos + 1 >= m_Text.Length || m_Text[m_Pos + 1] == ' ')) break;
                m_Pos++;
            }
            return m_Text.Substring(start, m_Pos - start).Trim();
        }

        char Peek() => m_Pos < m_Text.Length ? m_Text[m_Pos] : '\0';

        void SkipSpace()
        {
            while (m_Pos < m_Text.Length && (m_Text[m_Pos] == ' ' || m_Text[m_Pos] == '\n' || m_Text[m_Pos] == '\t')) m_Pos++;
        }

        System.FormatException Error(string message) => YamlError.At(m_File, m_Line, message + " in '" + m_Text + "'");
    }
}
