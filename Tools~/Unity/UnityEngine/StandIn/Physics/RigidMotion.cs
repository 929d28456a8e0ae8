using System;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: PhysX 4's per-step velocity update and pose integration of one dynamic body (Dy
    /// bodyCoreComputeUnconstrainedVelocity / integrateCore): gravity, then damping v·max(0, 1 − drag·dt), then the
    /// angular speed clamp; the centre of mass moves by v·dt and the rotation turns by the exact rotation of ω·dt.
    /// </summary>
    internal static class RigidMotion
    {
        /// <summary>Adds gravity (when enabled) and applies linear and angular damping, then clamps the angular speed.</summary>
        internal static void UpdateVelocity(ref Vector3 velocity, ref Vector3 angularVelocity, Vector3 gravity, bool useGravity,
            float drag, float angularDrag, float maxAngularSpeed, float dt)
        {
            if (useGravity) velocity += gravity * dt;
            float linear = 1f - drag * dt, angular = 1f - angularDrag * dt;
            velocity *= linear >= 0f ? linear : 0f;
            angularVelocity *= angular >= 0f ? angular : 0f;
            float speedSq = angularVelocity.sqrMagnitude;
            if (speedSq > maxAngularSpeed * maxAngularSpeed)
                angularVelocity *= (float)Math.Sqrt(maxAngularSpeed * maxAngularSpeed / speedSq);
        }

        /// <summary>The rotation <paramref name="q"/> turned about the world axis of <paramref name="angularVelocity"/> by |ω|·dt (closed form, then normalised).</summary>
        internal static Quaternion Integrate(Quaternion q, Vector3 angularVelocity, float dt)
        {
            float w = angularVelocity.magnitude;
            if (w == 0f) return q;
            float half = dt * w * 0.5f;
            float s = (float)Math.Sin(half) / w, c = (float)Math.Cos(half);
            var v = angularVelocity * s;
            // (v, 0) · q + q · c
            var r = new Quaternion(
                v.y * q.z - v.z * q.y + v.x * q.w + q.x * c,
                v.z * q.x - v.x * q.z + v.y * q.w + q.y * c,
                v.x * q.y - v.y * q.x + v.z * q.w + q.z * c,
                -(v.x * q.x + v.y * q.y + v.z * q.z) + q.w * c);
            return Quaternion.Normalize(r);
        }
    }
}
