using UnityEditor;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// Scene gizmos of an <see cref="ElasticRope"/>: in Play, every segment coloured by its tension
    /// (<see cref="TensionColorMap"/>, red at the larger of the peak tension and 1 N) and, when selected, each
    /// particle as a wire sphere of its current radius; in edit mode, the static-sag preview if one was computed,
    /// else the straight line between the attachments.
    /// </summary>
    static class ElasticRopeGizmos
    {
        [DrawGizmo(GizmoType.Selected | GizmoType.NonSelected)]
        static void Draw(ElasticRope rope, GizmoType type)
        {
            bool selected = (type & GizmoType.Selected) != 0;
            if (rope.IsBuilt)
            {
                DrawBuilt(rope, selected);
                return;
            }
            var preview = StaticSagPreview.Get(rope);
            if (preview.Length > 1)
            {
                Gizmos.color = Color.cyan;
                for (int i = 0; i + 1 < preview.Length; i++) Gizmos.DrawLine(preview[i], preview[i + 1]);
                return;
            }
            Vector3 start = rope.StartAttachment.WorldPosition(rope.transform.position);
            Vector3 end = rope.EndAttachment.WorldPosition(new Vector3(start.x, start.y - rope.RestLength, start.z));
            Gizmos.color = selected ? Color.yellow : Color.white;
            Gizmos.DrawLine(start, end);
        }

        static void DrawBuilt(ElasticRope rope, bool selected)
        {
            int particles = rope.ParticleCount;
            float reference = rope.PeakTension > 1f ? rope.PeakTension : 1f;
            Vector3 previous = rope.GetParticlePosition(0);
            for (int s = 0; s + 1 < particles; s++)
            {
                Vector3 next = rope.GetParticlePosition(s + 1);
                if (!rope.IsSegmentBroken(s))
                {
                    Gizmos.color = TensionColorMap.Evaluate(rope.GetSegmentTension(s), reference);
                    Gizmos.DrawLine(previous, next);
                }
                previous = next;
            }
            if (!selected) return;
            Gizmos.color = Color.white;
            for (int i = 0; i < particles; i++) Gizmos.DrawWireSphere(rope.GetParticlePosition(i), rope.GetParticleRadius(i));
        }
    }
}
