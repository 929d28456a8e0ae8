using System;
using System.Runtime.CompilerServices;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// The inspector's static-sag preview of an <see cref="ElasticRope"/>, computed in edit mode without entering
    /// Play: a detached core simulation of the rope's current settings and attachment poses (the same build path as
    /// <see cref="ElasticRope.Rebuild"/>) relaxes with its velocities damped, and the settled particle positions are
    /// kept for the scene gizmo.
    /// </summary>
    public static class StaticSagPreview
    {
        /// <summary>Host step of the relaxation (s).</summary>
        const float StepSeconds = 1f / 60f;

        /// <summary>Velocity scale applied after every relaxation step (dimensionless).</summary>
        const float VelocityScale = 0.85f;

        static readonly ConditionalWeakTable<ElasticRope, Vector3[]> s_Previews = new ConditionalWeakTable<ElasticRope, Vector3[]>();

        /// <summary>
        /// Computes the static sag of <paramref name="rope"/>'s current settings between its current attachment
        /// positions: a separate core rope relaxes for <paramref name="seconds"/> of simulated time (s) with its
        /// velocities scaled by 0.85 every 1/60 s step (a near-critical damping of the swing of a metre-scale rope),
        /// so it settles into the static shape; long ropes swing slowly and need more seconds. Returns the particle
        /// positions in world space (m), also kept for <see cref="Get"/>. The component itself is not built.
        /// </summary>
        public static Vector3[] Compute(ElasticRope rope, float seconds = 6f)
        {
            if (rope == null) throw new ArgumentNullException(nameof(rope));
            if (!(seconds > 0f) || float.IsInfinity(seconds))
                throw new ArgumentOutOfRangeException(nameof(seconds), seconds, "seconds must be in (0, +inf)");
            var core = rope.CreateDetachedSimulation(out Vector3 origin).Rope;
            int last = core.ParticleCount - 1;
            int steps = (int)Math.Ceiling(seconds / StepSeconds);
            for (int s = 0; s < steps; s++)
            {
                core.Step(StepSeconds);
                for (int i = 0; i <= last; i++) core.SetVelocity(i, core.GetVelocity(i) * VelocityScale);
            }
            var preview = new Vector3[core.ParticleCount];
            for (int i = 0; i <= last; i++)
            {
                var p = core.GetPosition(i);
                preview[i] = origin + new Vector3(p.X, p.Y, p.Z);
            }
            s_Previews.Remove(rope);
            s_Previews.Add(rope, preview);
            return preview;
        }

        /// <summary>The last preview computed for <paramref name="rope"/> (world, m), or an empty array.</summary>
        public static Vector3[] Get(ElasticRope rope) =>
            rope != null && s_Previews.TryGetValue(rope, out var preview) ? preview : Array.Empty<Vector3>();
    }
}
