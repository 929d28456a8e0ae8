using System;
using System.Globalization;
using HookeRope.Solver;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// The geometry of the inspector's force–elongation preview (issue 15 item 5): the material law's quasi-static curve
    /// (<see cref="ForceElongationCurve"/>) mapped into a GUI rectangle, elongation to the right and force upwards (GUI y
    /// grows downwards), both axes from zero to the curve's largest value plus <see cref="Headroom"/>; and the caption under
    /// it. Pure logic (no GUI), so it is tested headless; <see cref="MaterialLawInspector"/> draws it.
    /// </summary>
    internal static class ForceElongationPreview
    {
        /// <summary>Height of the preview in GUI pixels.</summary>
        public const float Height = 110f;

        /// <summary>Space above the highest force and right of the longest elongation, as a fraction of each axis.</summary>
        public const float Headroom = 0.08f;

        /// <summary>
        /// The curve's vertices in GUI coordinates inside the rectangle (<paramref name="x"/>, <paramref name="y"/>) of
        /// <paramref name="width"/> × <paramref name="height"/> pixels: (0 m, 0 N) at the bottom-left corner, the largest
        /// elongation and force at (1 − headroom) of the width and height.
        /// </summary>
        public static Vector3[] Points(ForceElongationCurve curve, float x, float y, float width, float height)
        {
            if (curve == null) throw new ArgumentNullException(nameof(curve));
            Scale(curve, out double elongation, out double force);
            var points = new Vector3[curve.Count];
            for (int i = 0; i < curve.Count; i++)
            {
                float u = (float)(curve.Elongation[i] / elongation), v = (float)(curve.Force[i] / force);
                points[i] = new Vector3(x + u * width, y + height - v * height, 0f);
            }
            return points;
        }

        /// <summary>The axis ranges (m, N) the preview spans: the largest elongation and force of the curve, with headroom; never zero.</summary>
        public static void Scale(ForceElongationCurve curve, out double elongation, out double force)
        {
            double e = 0.0, f = 0.0;
            for (int i = 0; i < curve.Count; i++)
            {
                e = Math.Max(e, curve.Elongation[i]);
                f = Math.Max(f, curve.Force[i]);
            }
            elongation = (e > 0.0 ? e : 1.0) / (1.0 - Headroom);
            force = (f > 0.0 ? f : 1.0) / (1.0 - Headroom);
        }

        /// <summary>The caption: the peak force and where, the break elongation (or the open end), with units.</summary>
        public static string Caption(ForceElongationCurve curve)
        {
            if (curve == null) throw new ArgumentNullException(nameof(curve));
            int peak = 0;
            for (int i = 1; i < curve.Count; i++) if (curve.Force[i] > curve.Force[peak]) peak = i;
            string text = "peak " + Force(curve.Force[peak]) + " at " + Metres(curve.Elongation[peak]);
            return double.IsNaN(curve.BreakElongation)
                ? text + " (elastic end at " + Metres(curve.Elongation[curve.Count - 1]) + ")"
                : text + "; breaks at " + Metres(curve.BreakElongation);
        }

        static string Force(double newtons) =>
            newtons >= 1000.0 ? (newtons / 1000.0).ToString("G4", CultureInfo.InvariantCulture) + " kN" : newtons.ToString("G4", CultureInfo.InvariantCulture) + " N";

        static string Metres(double metres) => metres.ToString("G4", CultureInfo.InvariantCulture) + " m";
    }
}
