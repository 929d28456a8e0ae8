using System;
using System.Collections.Generic;

namespace HookeRope.Lab.Commands
{
    /// <summary>"Did you mean …": the closest known name to a mistyped one (edit distance).</summary>
    public static class Suggestions
    {
        /// <summary>The candidate closest to <paramref name="typed"/> within about a third of its length in edits (at least 2), or null.</summary>
        public static string Closest(string typed, IEnumerable<string> candidates)
        {
            if (string.IsNullOrEmpty(typed)) return null;
            string best = null;
            int bestDistance = int.MaxValue;
            foreach (var candidate in candidates)
            {
                int d = Distance(typed.ToLowerInvariant(), candidate.ToLowerInvariant());
                if (candidate.StartsWith(typed, StringComparison.OrdinalIgnoreCase) && typed.Length >= 3) d = Math.Min(d, 1);
                if (d < bestDistance)
                {
                    bestDistance = d;
                    best = candidate;
                }
            }
            return bestDistance <= Math.Max(2, typed.Length / 3) ? best : null;
        }

        /// <summary>" (did you mean …?)" or "" when nothing is close.</summary>
        public static string DidYouMean(string typed, IEnumerable<string> candidates)
        {
            string closest = Closest(typed, candidates);
            return closest == null ? "" : $" (did you mean \"{closest}\"?)";
        }

        /// <summary>Levenshtein distance: insertions, deletions and substitutions turning <paramref name="a"/> into <paramref name="b"/>.</summary>
        public static int Distance(string a, string b)
        {
            var previous = new int[b.Length + 1];
            var current = new int[b.Length + 1];
            for (int j = 0; j <= b.Length; j++) previous[j] = j;
            for (int i = 1; i <= a.Length; i++)
            {
                current[0] = i;
                for (int j = 1; j <= b.Length; j++)
                {
                    int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
                    current[j] = Math.Min(substitution, Math.Min(previous[j] + 1, current[j - 1] + 1));
                }
                var swap = previous;
                previous = current;
                current = swap;
            }
            return previous[b.Length];
        }
    }
}
