using System.Collections.Generic;
using System.Text;
using System.Text.RegularExpressions;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: reads Unity's YAML asset files (prefabs, scenes): the %YAML/%TAG directives, one document
    /// per object ("--- !u!&lt;classID&gt; &amp;&lt;fileID&gt;"), block mappings and sequences (including Unity's
    /// sequences at the indentation of their key), flow collections and plain or quoted scalars. Anything else
    /// (tabs, block scalars, anchors other than the document header) is an error naming the file and line.
    /// </summary>
    internal sealed class UnityYamlParser
    {
        static readonly Regex Header = new Regex(@"^--- !u!(\d+) &(-?\d+)( stripped)?\s*$");
        readonly string m_File;
        readonly string[] m_Raw;
        int m_Index, m_Col, m_End;

        UnityYamlParser(string text, string file)
        {
            m_File = file;
            m_Raw = text.Replace("\r\n", "\n").Replace('\r', '\n').Split('\n');
        }

        /// <summary>The objects of the Unity YAML file <paramref name="file"/> whose text is <paramref name="text"/>.</summary>
        internal static List<UnityYamlDocument> Parse(string text, string file) => new UnityYamlParser(text, file).Documents();

        List<UnityYamlDocument> Documents()
        {
            var documents = new List<UnityYamlDocument>();
            int i = 0;
            for (; i < m_Raw.Length && !m_Raw[i].StartsWith("---", System.StringComparison.Ordinal); i++)
            {
                string line = m_Raw[i].Trim();
                if (line.Length == 0 || line.StartsWith("%YAML", System.StringComparison.Ordinal) || line.StartsWith("%TAG", System.StringComparison.Ordinal)) continue;
                throw YamlError.At(m_File, i + 1, "expected %YAML/%TAG directives or a '--- !u!' document header, found '" + line + "'");
            }
            if (i == m_Raw.Length) throw YamlError.At(m_File, 1, "no Unity object ('--- !u!<classID> &<fileID>') in the file");
            while (i < m_Raw.Length)
            {
                var match = Header.Match(m_Raw[i]);
                if (!match.Success) throw YamlError.At(m_File, i + 1, "malformed document header '" + m_Raw[i] + "'");
                int headerLine = i + 1;
                int end = i + 1;
                while (end < m_Raw.Length && !m_Raw[end].StartsWith("---", System.StringComparison.Ordinal)) end++;
                documents.Add(Document(match, headerLine, i + 1, end));
                i = end;
            }
            return documents;
        }

        UnityYamlDocument Document(Match header, int headerLine, int start, int end)
        {
            int classId = int.Parse(header.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
            long fileId = long.Parse(header.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture);
            m_Index = start;
            m_Col = 0;
            m_End = end;
            SkipBlank();
            if (m_Index >= m_End) throw YamlError.At(m_File, headerLine, "object &" + fileId + " has no type line");
            string typeLine = m_Raw[m_Index];
            if (Indent() != 0 || !typeLine.TrimEnd().EndsWith(":", System.StringComparison.Ordinal))
                throw YamlError.At(m_File, m_Index + 1, "expected '<TypeName>:' after the document header, found '" + typeLine.Trim() + "'");
            string typeName = typeLine.TrimEnd().TrimEnd(':');
            var body = new YamlMapping(m_Index + 1);
            Advance();
            if (m_Index < m_End)
            {
                if (Indent() == 0) throw YamlError.At(m_File, m_Index + 1, "unexpected text at column 1 inside object &" + fileId);
                body = ParseMapping(Indent());
                if (m_Index < m_End) throw YamlError.At(m_File, m_Index + 1, "unexpected indentation of '" + Text() + "'");
            }
            return new UnityYamlDocument(classId, fileId, header.Groups[3].Success, typeName, body, headerLine);
        }

        // ---- block structure ----------------------------------------------------------------------------------
        YamlNode ParseBlock()
        {
            int indent = Indent();
            return IsItem(Text()) ? ParseSequence(indent) : ParseMapping(indent);
        }

        YamlMapping ParseMapping(int indent)
        {
            var map = new YamlMapping(m_Index + 1);
            while (m_Index < m_End)
            {
                int current = Indent();
                if (current < indent) break;
                if (current > indent) throw YamlError.At(m_File, m_Index + 1, "unexpected indentation of '" + Text() + "'");
                string text = Text();
                if (IsItem(text)) break;
                int colon = KeyColon(text);
                if (colon < 0) throw YamlError.At(m_File, m_Index + 1, "expected 'key: value', found '" + text + "'");
                string key = text.Substring(0, colon).Trim();
                string rest = text.Substring(colon + 1).Trim();
                int keyLine = m_Index + 1;
                YamlNode value;
                if (rest.Length == 0)
                {
                    Advance();
                    if (m_Index < m_End && Indent() > indent) value = ParseBlock();
                    else if (m_Index < m_End && Indent() == indent && IsItem(Text())) value = ParseSequence(indent);
                    else value = new YamlScalar("", false, keyLine);
                }
                else value = InlineValue(rest, indent, keyLine);
                if (map.Find(key) != null) throw YamlError.At(m_File, keyLine, "duplicate key '" + key + "'");
                map.Add(new YamlEntry(key, value, keyLine));
            }
            return map;
        }

        YamlSequence ParseSequence(int indent)
        {
            var seq = new YamlSequence(m_Index + 1);
            while (m_Index < m_End && Indent() == indent && IsItem(Text()))
            {
                int itemLine = m_Index + 1;
                string text = Text();
                string rest = text.Length > 1 ? text.Substring(2) : "";
                int restCol = indent + 2 + (rest.Length - rest.TrimStart().Length);
                rest = rest.Trim();
                YamlNode item;
                if (rest.Length == 0)
                {
                    Advance();
                    item = m_Index < m_End && Indent() > indent ? ParseBlock() : new YamlScalar("", false, itemLine);
                }
                else if (IsItem(rest)) { m_Col = restCol; item = ParseSequence(restCol); }
                else if (rest[0] != '{' && rest[0] != '[' && rest[0] != '\'' && rest[0] != '"' && KeyColon(rest) >= 0)
                {
                    m_Col = restCol;
                    item = ParseMapping(restCol);
                }
                else item = InlineValue(rest, indent, itemLine);
                seq.Add(item);
            }
            return seq;
        }

        /// <summary>A value that starts on the key's (or item's) line; consumes that line and its continuation lines.</summary>
        YamlNode InlineValue(string rest, int parentIndent, int line)
        {
            char first = rest[0];
            if (first == '|' || first == '>') throw YamlError.At(m_File, line, "block scalars ('" + first + "') are not supported");
            if (first == '&' || first == '*' || first == '!') throw YamlError.At(m_File, line, "anchors, aliases and tags inside an object are not supported");
            if (first == '{' || first == '[')
            {
                var sb = new StringBuilder(rest);
                Advance();
                while (!YamlFlowParser.IsComplete(sb.ToString()))
                {
                    if (m_Index >= m_End) throw YamlError.At(m_File, line, "unterminated flow collection '" + rest + "'");
                    sb.Append('\n').Append(m_Raw[m_Index].Trim());
                    Advance();
                }
                return YamlFlowParser.Parse(sb.ToString(), m_File, line);
            }
            if (first == '\'' || first == '"') return QuotedValue(rest, line);
            var plain = new StringBuilder(rest);
            Advance();
            while (m_Index < m_End && Indent() > parentIndent)
            {
                if (KeyColon(Text()) >= 0 || IsItem(Text()))
                    throw YamlError.At(m_File, m_Index + 1, "unexpected indentation of '" + Text() + "' (a value cannot continue with a key or item)");
                plain.Append('\n').Append(m_Raw[m_Index].Trim());
                Advance();
            }
            return new YamlScalar(YamlScalarText.Fold(plain.ToString()), false, line);
        }

        YamlScalar QuotedValue(string rest, int line)
        {
            char quote = rest[0];
            var raw = new StringBuilder(rest.Substring(1));
            int rawLine = m_Index;
            while (true)
            {
                int close = ClosingQuote(raw.ToString(), quote);
                if (close >= 0)
                {
                    string after = raw.ToString().Substring(close + 1).Trim();
                    if (after.Length > 0) throw YamlError.At(m_File, line, "unexpected '" + after + "' after a quoted scalar");
                    string inner = raw.ToString().Substring(0, close);
                    string value = quote == '\'' ? YamlScalarText.SingleQuoted(inner) : YamlScalarText.DoubleQuoted(inner);
                    if (value == null) throw YamlError.At(m_File, line, "malformed escape in a double-quoted scalar");
                    m_Index = rawLine;
                    m_Col = 0;
                    Advance();
                    return new YamlScalar(value, true, line);
                }
                rawLine++;
                if (rawLine >= m_End) throw YamlError.At(m_File, line, "unterminated quoted scalar");
                raw.Append('\n').Append(m_Raw[rawLine]);
            }
        }

        static int ClosingQuote(string text, char quote)
        {
            for (int i = 0; i < text.Length; i++)
            {
                char c = text[i];
                if (quote == '"' && c == '\\') { i++; continue; }
                if (c != quote) continue;
                if (quote == '\'' && i + 1 < text.Length && text[i + 1] == '\'') { i++; continue; }
                return i;
            }
            return -1;
        }

        // ---- lines -------------------------------------------------------------------------------------------
        static bool IsItem(string text) => text == "-" || text.StartsWith("- ", System.StringComparison.Ordinal);

        /// <summary>Index of the ':' that ends a plain key ("key: value" or "key:"), or -1.</summary>
        static int KeyColon(string text)
        {
            for (int i = 0; i < text.Length; i++)
            {
                char c = text[i];
                if (c == '{' || c == '[' || c == '\'' || c == '"') return -1;
                if (c == ':' && (i + 1 == text.Length || text[i + 1] == ' ')) return i > 0 ? i : -1;
            }
            return -1;
        }

        int Indent()
        {
            string line = m_Raw[m_Index];
            int i = m_Col;
            while (i < line.Length && line[i] == ' ') i++;
            if (i < line.Length && line[i] == '\t') throw YamlError.At(m_File, m_Index + 1, "tab in indentation");
            return i;
        }

        string Text() => m_Raw[m_Index].Substring(Indent()).TrimEnd();

        void Advance()
        {
            m_Index++;
            m_Col = 0;
            SkipBlank();
        }

        void SkipBlank()
        {
            while (m_Index < m_End)
            {
                string t = m_Raw[m_Index].Trim();
                if (t.Length != 0 && t[0] != '#') break;
                m_Index++;
            }
        }
    }
}
