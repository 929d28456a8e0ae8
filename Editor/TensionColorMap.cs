using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>Colour map for segment tension in the scene gizmos: blue (slack) → green → yellow → red (at the reference tension).</summary>
    internal static class TensionColorMap
    {
        static readonly Color Slack = new Color(0.2f, 0.4f, 1f);
        static readonly Color Low = new Color(0.1f, 0.9f, 0.3f);
        static readonly Color Mid = new Color(1f, 0.9f, 0.1f);
        static readonly Color High = new Color(1f, 0.15f, 0.1f);

        /// <summary>Colour for <paramref name="tension"/> (N) against <paramref name="reference"/> (N, &gt; 0): 0 → blue, reference → red.</summary>
        public static Color Evaluate(float tension, float reference)
        {
            float t = reference > 0f ? tension / reference : 0f;
            if (!(t > 0f)) return Slack;
            if (t >= 1f) return High;
            if (t < 1f / 3f) return Color.Lerp(Slack, Low, t * 3f);
            if (t < 2f / 3f) return Color.Lerp(Low, Mid, t * 3f - 1f);
            return Color.Lerp(Mid, High, t * 3f - 2f);
        }
    }
}
