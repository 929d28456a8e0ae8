using System;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Scenarios
{
    /// <summary>Initial rope shapes and the end positions a scenario implies (metres).</summary>
    public static class ScenarioGeometry
    {
        /// <summary>Unit vector along gravity, or −Y when gravity is zero.</summary>
        public static Float3 DownDirection(Float3 gravity) => gravity.NormalizedOr(new Float3(0f, -1f, 0f));

        /// <summary>Position of particle 0 at t = 0.</summary>
        public static Float3 StartPosition(Scenario s) => s.Start.Kind == AttachmentKind.Keyframes
            ? s.Start.Keys[0].Position
            : s.Start.Position ?? Float3.Zero;

        /// <summary>Position of the last particle at t = 0 (derived when the scenario does not give it).</summary>
        public static Float3 EndPosition(Scenario s)
        {
            if (s.End.Kind == AttachmentKind.Keyframes) return s.End.Keys[0].Position;
            if (s.End.Position.HasValue) return s.End.Position.Value;
            var down = DownDirection(s.Gravity);
            float length = (float)s.Rope.RestLength;
            if (s.Initial.FallHeight.HasValue)
                return StartPosition(s) - down * (float)(s.Initial.FallHeight.Value - s.Rope.RestLength);
            return StartPosition(s) + down * (length * (float)(1.0 + s.Initial.Stretch));
        }

        /// <summary>Fills <paramref name="positions"/> (SegmentCount + 1 entries) with the initial shape.</summary>
        public static void InitialPositions(Scenario s, Float3[] positions)
        {
            var a = StartPosition(s);
            var b = EndPosition(s);
            int n = positions.Length - 1;
            double length = s.Rope.RestLength;
            var chord = b - a;
            double d = chord.Length;
            if (s.Initial.Shape == InitialShape.Straight || d >= length * (1 - 1e-9))
            {
                for (int i = 0; i <= n; i++) positions[i] = Float3.Lerp(a, b, (float)i / n);
                return;
            }
            var down = DownDirection(s.Gravity);
            var axis = chord.NormalizedOr(new Float3(1f, 0f, 0f));
            var side = down - axis * Float3.Dot(down, axis);
            if (side.Length < 1e-4f) side = Float3.Cross(axis, new Float3(0f, 0f, 1f));
            if (side.Length < 1e-4f) side = Float3.Cross(axis, new Float3(1f, 0f, 0f));
            side = side.NormalizedOr(new Float3(1f, 0f, 0f));
            if (s.Initial.Shape == InitialShape.Catenary)
            {
                double c = CatenaryParameter(d, length);
                double half = d / 2;
                double top = c * Math.Cosh(half / c);
                for (int i = 0; i <= n; i++)
                {
                    double arc = -length / 2 + length * i / n;
                    double x = c * Math.Asinh(arc / c);
                    double y = c * Math.Cosh(x / c) - top;  // ≤ 0: below the supports
                    positions[i] = a + axis * (float)(x + half) - side * (float)y;
                }
                positions[0] = a;
                positions[n] = b;
                return;
            }
            // Slack: a V of two straight legs of length L/2 whose apex hangs along gravity.
            double depth = Math.Sqrt(Math.Max(0, length * length / 4 - d * d / 4));
            var apex = Float3.Lerp(a, b, 0.5f) + side * (float)depth;
            for (int i = 0; i <= n; i++)
            {
                double arc = length * i / n;
                positions[i] = arc <= length / 2
                    ? Float3.Lerp(a, apex, (float)(arc / (length / 2)))
                    : Float3.Lerp(apex, b, (float)((arc - length / 2) / (length / 2)));
            }
        }

        /// <summary>Catenary parameter a (m) with 2a·sinh(D/(2a)) = S, for span D &lt; length S.</summary>
        public static double CatenaryParameter(double span, double length)
        {
            // f(a) = 2a sinh(D/2a) − S decreases in a; bracket and bisect in log space.
            double lo = span * 1e-4, hi = span * 1e6;
            for (int i = 0; i < 200; i++)
            {
                double mid = Math.Sqrt(lo * hi);
                double f = 2 * mid * Math.Sinh(span / (2 * mid)) - length;
                if (double.IsInfinity(f) || f > 0) lo = mid; else hi = mid;
            }
            return Math.Sqrt(lo * hi);
        }

        /// <summary>Sag (m) of the catenary of length S over span D: a·cosh(D/2a) − a.</summary>
        public static double CatenarySag(double span, double length)
        {
            double a = CatenaryParameter(span, length);
            return a * Math.Cosh(span / (2 * a)) - a;
        }
    }
}
