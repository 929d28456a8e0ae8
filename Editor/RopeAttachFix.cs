using UnityEditor;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// The inspector's one-click fix for a rope that is half on a rig: an end's Point sits under a Rigidbody while
    /// that end's Body is empty, so the rig would be pinned like a Transform instead of pulled. <see cref="For"/>
    /// decides whether the rope needs it and what it would do (the self-wiring of <see cref="RopeAutoWiring"/>:
    /// End onto the body at its D-ring, Start onto a root-level anchor above it, snapped to the beam within reach); <see cref="Apply"/> does it with Undo.
    /// The IMGUI part (HelpBox and button) is in <see cref="ElasticRopeEditor"/>.
    /// </summary>
    internal sealed class RopeAttachFix
    {
        readonly ElasticRope _rope;
        readonly RopeAutoWiring _wiring;

        RopeAttachFix(ElasticRope rope, RopeAutoWiring wiring)
        {
            _rope = rope;
            _wiring = wiring;
        }

        /// <summary>The body the End would pull two-way.</summary>
        internal Rigidbody Body => _wiring.Body;

        /// <summary>The End's attachment point on <see cref="Body"/> (the D-ring), or null for the body's position.</summary>
        internal Transform EndPoint => _wiring.EndPoint;

        /// <summary>True when the Start would move onto a root-level anchor.</summary>
        internal bool MovesStart => _wiring.RewiresStart;

        /// <summary>Where that anchor would be (m, world): on the beam's underside when one is within reach, else the rest length above the D-ring.</summary>
        internal Vector3 AnchorPosition => _wiring.AnchorPosition;

        /// <summary>The collider (beam) the anchor would be snapped to, or null.</summary>
        internal Collider Beam => _wiring.Beam;

        /// <summary>The button's label: "Attach to &lt;body name&gt;".</summary>
        internal string ButtonLabel => "Attach to " + Body.name;

        /// <summary>The HelpBox text.</summary>
        internal string Message =>
            "An end's Point sits under the Rigidbody '" + Body.name + "' but its Body is empty: the rope would pin it like a Transform instead of arresting it. " +
            "The fix: " + _wiring.Describe();

        /// <summary>
        /// The fix <paramref name="rope"/> needs, or null: only when an end's Point sits under a Rigidbody while that
        /// end's Body is empty, and wiring would change something.
        /// </summary>
        internal static RopeAttachFix For(ElasticRope rope)
        {
            if (rope == null) return null;
            if (RopeAutoWiring.BodyAbovePoint(rope.StartAttachment) == null && RopeAutoWiring.BodyAbovePoint(rope.EndAttachment) == null) return null;
            var wiring = RopeAutoWiring.For(rope);
            return wiring == null ? null : new RopeAttachFix(rope, wiring);
        }

        /// <summary>Wires the rope (Undo-able: the rope's fields and the created anchor).</summary>
        internal void Apply() => Apply(_rope, _wiring, ButtonLabel);

        /// <summary>
        /// Carries out <paramref name="wiring"/> on <paramref name="rope"/> with Undo named <paramref name="undoName"/>:
        /// the rope's fields recorded, a created anchor registered (shared with the drop hook, <see cref="RopeDropWiring"/>).
        /// </summary>
        internal static void Apply(ElasticRope rope, RopeAutoWiring wiring, string undoName)
        {
            Undo.RecordObject(rope, undoName);
            var created = wiring.Apply();
            if (created != null) Undo.RegisterCreatedObjectUndo(created, undoName);
        }
    }
}
