using System;
using System.Runtime.CompilerServices;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// The static-sag preview of an <see cref="ElasticRope"/> in edit mode, shared by the editor (inspector button,
    /// scene gizmo) and <see cref="RopeMeshRenderer"/>'s edit-mode drawing: a detached core simulation of the rope's
    /// current settings and attachment poses (<see cref="ElasticRope.CreateDetachedSimulation"/>, the Rebuild path)
    /// relaxes with its velocities damped, and the settled particle positions (world, m) are kept per rope. Once a
    /// preview was computed, <see cref="GetFollowing"/> recomputes it when an end moved or the segment count changed,
    /// so the drawn sag follows dragged ends.
    /// </summary>
    internal static class RopeStaticSag
    {
        /// <summary>Host step of the relaxation (s).</summary>
        const float StepSeconds = 1f / 60f;

        /// <summary>Velocity scale applied after every relaxation step (dimensionless).</summary>
        const float VelocityScale = 0.85f;

        /// <summary>An end that moved by more than this (m) recomputes the preview.</summary>
        const float MoveTolerance = 1e-4f;

        sealed class Entry
        {
            public Vector3[] Positions;
            public float Seconds;
            public Vector3 Start, End;
        }

        static readonly ConditionalWeakTable<ElasticRope, Entry> s_Previews = new ConditionalWeakTable<ElasticRope, Entry>();

        /// <summary>Relaxes <paramref name="rope"/>'s current settings for <paramref name="seconds"/> (s) and keeps the result.</summary>
        internal static Vector3[] Compute(ElasticRope rope, float seconds)
        {
            if (rope == null) throw new ArgumentNullException(nameof(rope));
            if (!(seconds > 0f) || float.IsInfinity(seconds))
                throw new ArgumentOutOfRangeException(nameof(seconds), seconds, "seconds must be in (0, +inf)");
            Ends(rope, out Vector3 start, out Vector3 end);
            var core = rope.CreateDetachedSimulation(out Vector3 origin).Rope;
            int last = core.ParticleCount - 1;
            int steps = (int)Math.Ceiling(seconds / StepSeconds);
            for (int s = 0; s < steps; s++)
            {
                core.Step(StepSeconds);
                for (int i = 0; i <= last; i++) core.SetVelocity(i, core.GetVelocity(i) * VelocityScale);
            }
            var preview = new Vector3[core.ParticleCount];
            for (int i = 0; i <= last; i++) preview[i] = origin + core.GetPosition(i).ToVector3();
            s_Previews.Remove(rope);
            s_Previews.Add(rope, new Entry { Positions = preview, Seconds = seconds, Start = start, End = end });
            return preview;
        }

        /// <summary>The last preview computed for <paramref name="rope"/> (world, m) as it was computed, or an empty array.</summary>
        internal static Vector3[] Get(ElasticRope rope) =>
            rope != null && s_Previews.TryGetValue(rope, out var entry) ? entry.Positions : Array.Empty<Vector3>();

        /// <summary>
        /// The preview of <paramref name="rope"/> recomputed first when one was computed and an end moved or the
        /// segment count changed since; an empty array when none was computed.
        /// </summary>
        internal static Vector3[] GetFollowing(ElasticRope rope)
        {
            if (rope == null || !s_Previews.TryGetValue(rope, out var entry)) return Array.Empty<Vector3>();
            Ends(rope, out Vector3 start, out Vector3 end);
            bool moved = (start - entry.Start).sqrMagnitude > MoveTolerance * MoveTolerance ||
                         (end - entry.End).sqrMagnitude > MoveTolerance * MoveTolerance;
            if (moved || entry.Positions.Length != rope.SegmentCount + 1) return Compute(rope, entry.Seconds);
            return entry.Positions;
        }

        /// <summary>Forgets the preview of <paramref name="rope"/>.</summary>
        internal static void Clear(ElasticRope rope)
        {
            if (rope != null) s_Previews.Remove(rope);
        }

        /// <summary>The attachment positions the rope would be built between (world, m), as in the Rebuild path.</summary>
        internal static void Ends(ElasticRope rope, out Vector3 start, out Vector3 end)
        {
            start = rope.StartAttachment.WorldPosition(rope.transform.position);
            end = rope.EndAttachment.WorldPosition(new Vector3(start.x, start.y - rope.RestLength, start.z));
        }
    }
}
