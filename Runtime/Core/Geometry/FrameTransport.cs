using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Parallel transport of a ring frame: the normal is rotated by the smallest rotation that takes the old
    /// tangent to the new one, so the tube does not twist; a half-turn reversal keeps the normal.
    /// </summary>
    internal static class FrameTransport
    {
        /// <summary>
        /// Transports unit <paramref name="normal"/> (perpendicular to unit <paramref name="fromTangent"/>) to a unit
        /// normal perpendicular to unit <paramref name="toTangent"/>. Never returns NaN for unit inputs.
        /// </summary>
        public static Float3 Transport(Float3 normal, Float3 fromTangent, Float3 toTangent)
        {
            float c = Float3.Dot(fromTangent, toTangent);
            Float3 moved = normal;
            if (c > -0.9999f)
            {
                Float3 k = Float3.Cross(fromTangent, toTangent);
                moved = normal * c + Float3.Cross(k, normal) + k * (Float3.Dot(k, normal) / (1f + c));
            }
            return Perpendicular(moved, toTangent);
        }

        /// <summary>
        /// <paramref name="candidate"/> made perpendicular to unit <paramref name="tangent"/> and unit length; when
        /// that degenerates, a unit vector perpendicular to the tangent built from the least-aligned axis.
        /// </summary>
        public static Float3 Perpendicular(Float3 candidate, Float3 tangent)
        {
            Float3 p = candidate - tangent * Float3.Dot(candidate, tangent);
            float lengthSquared = p.LengthSquared;
            if (lengthSquared > 1e-8f && float.IsFinite(lengthSquared)) return p * (1f / System.MathF.Sqrt(lengthSquared));
            float ax = System.MathF.Abs(tangent.X), ay = System.MathF.Abs(tangent.Y), az = System.MathF.Abs(tangent.Z);
            Float3 axis = ax <= ay && ax <= az ? new Float3(1f, 0f, 0f) : (ay <= az ? new Float3(0f, 1f, 0f) : new Float3(0f, 0f, 1f));
            Float3 q = axis - tangent * Float3.Dot(axis, tangent);
            return q.NormalizedOr(new Float3(1f, 0f, 0f));
        }
    }
}
