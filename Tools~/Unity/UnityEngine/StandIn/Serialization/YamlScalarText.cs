using System.Globalization;
using System.Text;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: YAML 1.1 scalar text rules Unity's files use: line folding (a single line break becomes a
    /// space, each empty line a newline, indentation of continuation lines dropped), single quotes ('' = ') and
    /// double-quoted escapes (\n, \t, \", \\, \xXX, \uXXXX, \ at the end of a line joins without a space).
    /// </summary>
    internal static class YamlScalarText
    {
        /// <summary>Folds the raw lines of a multi-line scalar (joined with '\n').</summary>
        internal static string Fold(string raw)
        {
            if (raw.IndexOf('\n') < 0) return raw;
            var lines = raw.Split('\n');
            var sb = new StringBuilder(lines[0].TrimEnd());
            int empty = 0;
            for (int i = 1; i < lines.Length; i++)
            {
                string line = lines[i].Trim();
                if (line.Length == 0) { empty++; continue; }
                if (empty > 0) sb.Append('\n', empty);
                else if (sb.Length > 0 && sb[sb.Length - 1] == '\u0001') sb.Length--;
                else sb.Append(' ');
                empty = 0;
                sb.Append(line);
            }
            if (empty > 0) sb.Append('\n', empty);
            return sb.ToString();
        }

        /// <summary>The content of a single-quoted scalar (without its quotes).</summary>
        internal static string SingleQuoted(string inner) => Fold(inner).Replace("''", "'");

        /// <summary>The content of a double-quoted scalar (without its quotes); null when an escape is malformed.</summary>
        internal static string DoubleQuoted(string inner)
        {
            // An escaped line break joins the lines without a space: mark it so Fold drops the separator.
            var marked = new StringBuilder(inner.Length);
            for (int i = 0; i < inner.Length; i++)
            {
                if (inner[i] == '\\' && i + 1 < inner.Length && inner[i + 1] == '\n') { marked.Append('\u0001'); continue; }
                marked.Append(inner[i]);
            }
            string folded = Fold(marked.ToString()).Replace("\u0001", "");
            var sb = new StringBuilder(folded.Length);
            for (int i = 0; i < folded.Length; i++)
            {
                char c = folded[i];
                if (c != '\\') { sb.Append(c); continue; }
                if (++i >= folded.Length) return null;
                switch (folded[i])
                {
                    case 'n': sb.Append('\n'); break;
                    case 't': sb.Append('\t'); break;
                    case 'r': sb.Append('\r'); break;
                    case '0': sb.Append('\0'); break;
                    case '"': sb.Append('"'); break;
                    case '\\': sb.Append('\\'); break;
                    case '/': sb.Append('/'); break;
                    case ' ': sb.Append(' '); break;
                    case 'x': if (!Hex(folded, ref i, 2, sb)) return null; break;
                    case 'u': if (!Hex(folded, ref i, 4, sb)) return null; break;
                    default: return null;
                }
            }
            return sb.ToString();
        }

        static bool Hex(string s, ref int i, int digits, StringBuilder sb)
        {
            if (i + digits > s.Length - 1) return false;
            if (!int.TryParse(s.Substring(i + 1, digits), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out int code)) return false;
            sb.Append((char)code);
            i += digits;
            return true;
        }
    }
}
