using System.Collections.Generic;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// Self-wiring of an <see cref="ElasticRope"/> dropped onto a harness rig (a hierarchy with a Rigidbody): the End
    /// becomes a two-way load on the rig's body at its D-ring (a Transform in the body's hierarchy named like
    /// "D-ring", "Dring", "D ring" or "Harness Attachment", case-insensitive, spaces/hyphens/underscores ignored; else
    /// the body's position), and the Start becomes an anchor outside the rig: a root-level "&lt;rope name&gt; Anchor",
    /// created or reused, placed against gravity above the D-ring: on the first collider a ray from the D-ring hits
    /// within the rest length (the beam's underside; see <see cref="FindBeam"/>), else the rest length above it. An
    /// instance is the plan for one rope, made by <see cref="For"/> (null when nothing needs wiring) and carried out by
    /// <see cref="Apply"/>.
    /// The rope object itself stays where it is: once both ends are wired its pose carries neither end (the mesh is
    /// rebuilt from world positions every frame), and Unity refuses to re-parent objects inside a prefab instance.
    /// </summary>
    internal sealed class RopeAutoWiring
    {
        /// <summary>The rig's body the End will pull two-way.</summary>
        internal Rigidbody Body { get; }

        /// <summary>The End's attachment point on <see cref="Body"/> (the D-ring), or null for the body's position.</summary>
        internal Transform EndPoint { get; }

        /// <summary>True when the Start must be moved onto an anchor outside the rig.</summary>
        internal bool RewiresStart { get; }

        /// <summary>World position (m) of the anchor the Start gets when <see cref="RewiresStart"/>.</summary>
        internal Vector3 AnchorPosition { get; }

        /// <summary>The collider the anchor is snapped to (the beam), or null when none is within reach.</summary>
        internal Collider Beam { get; }

        /// <summary>Distance (m) from the D-ring up to <see cref="AnchorPosition"/>: the hit distance, else the rest length.</summary>
        internal float AnchorHeight { get; }

        /// <summary>Name of the root-level anchor object (created or reused).</summary>
        internal string AnchorName { get; }

        readonly ElasticRope _rope;

        RopeAutoWiring(ElasticRope rope, Rigidbody body, Transform endPoint, bool rewiresStart, Vector3 anchorPosition, Collider beam, float anchorHeight)
        {
            _rope = rope;
            Body = body;
            EndPoint = endPoint;
            RewiresStart = rewiresStart;
            AnchorPosition = anchorPosition;
            Beam = beam;
            AnchorHeight = anchorHeight;
            AnchorName = rope.name + " Anchor";
        }

        /// <summary>
        /// The rig body of <paramref name="rope"/>: the first Rigidbody in the rope's own parents, else the one above an
        /// end's Point while that end has no Body (a Point dragged onto the rig); null when there is none.
        /// </summary>
        internal static Rigidbody FindRig(ElasticRope rope)
        {
            if (rope == null) return null;
            var body = rope.GetComponentInParent<Rigidbody>();
            if (body != null) return body;
            return BodyAbovePoint(rope.EndAttachment) ?? BodyAbovePoint(rope.StartAttachment);
        }

        /// <summary>The Rigidbody above <paramref name="end"/>'s Point while that end has no Body (a Point dragged onto a rig); else null.</summary>
        internal static Rigidbody BodyAbovePoint(RopeEnd end)
        {
            if (end.Body != null || end.Point == null) return null;
            var body = end.Point.GetComponentInParent<Rigidbody>();
            return body != null ? body : null;
        }

        /// <summary>What wiring <paramref name="rope"/> onto its rig would do, or null when it has no rig or is already wired.</summary>
        internal static RopeAutoWiring For(ElasticRope rope)
        {
            var body = FindRig(rope);
            if (body == null) return null;
            var rig = body.transform;
            var end = rope.EndAttachment;
            var start = rope.StartAttachment;

            // keep an End Point the user already put on the body; else the D-ring, else the body's position
            var endPoint = end.Point != null && IsInside(end.Point, rig) && !IsInside(end.Point, rope.transform) ? end.Point : FindDRing(rig, rope.transform);
            bool rewiresStart = start.Body == body || (start.Body == null && (start.Point == null || IsInside(start.Point, rig)));
            if (end.Body == body && end.Point == endPoint && !rewiresStart) return null;

            Vector3 dRing = endPoint != null ? endPoint.position : body.position;
            Vector3 up = rope.Gravity.sqrMagnitude > 0f ? -rope.Gravity.normalized : Vector3.up;
            float reach = rope.RestLength;
            Collider beam = null;
            float height = reach;
            if (rewiresStart && FindBeam(dRing, up, reach, rig, rope.transform, out var hit))
            {
                beam = hit.collider;
                height = hit.distance;
            }
            return new RopeAutoWiring(rope, body, endPoint, rewiresStart, dRing + up * height, beam, height);
        }

        /// <summary>
        /// The plan for a rope just dropped onto a rig (Awake in Play, the editor's drop hook in Edit mode): as
        /// <see cref="For"/>, but null unless the rope sits under a Rigidbody and its End has no Body yet (an End.Body
        /// the user set is kept).
        /// </summary>
        internal static RopeAutoWiring ForDrop(ElasticRope rope) =>
            rope != null && rope.EndAttachment.Body == null && rope.GetComponentInParent<Rigidbody>() != null ? For(rope) : null;

        /// <summary>
        /// The console line logged when the rope is wired; compose it before <see cref="Apply"/> (afterwards a new
        /// anchor reads as an existing one).
        /// </summary>
        internal string WiredLine() => "HookeRope wired onto the rig: " + Describe();

        /// <summary>
        /// The beam above the D-ring: the nearest collider a ray from <paramref name="dRing"/> along the unit
        /// <paramref name="up"/> enters within <paramref name="reach"/> m (the rest length, so the rope is never
        /// pre-stretched at build), on Physics.DefaultRaycastLayers, triggers ignored, leaving out colliders in the
        /// rig's hierarchy (or attached to its body) and in the rope's own. In edit mode Transform changes are synced
        /// into physics first (Physics.autoSyncTransforms is off by default), so a beam just moved in the Scene view is
        /// found where it is; in Play the query sees the poses of the last step, as any query does (a sync there would
        /// also push interpolated Transforms into the bodies). Allocates (RaycastAll): once per wiring, never per step.
        /// </summary>
        static bool FindBeam(Vector3 dRing, Vector3 up, float reach, Transform rig, Transform rope, out RaycastHit nearest)
        {
            nearest = default;
            if (!(reach > 0f)) return false;
            if (!Application.isPlaying) Physics.SyncTransforms();
            var hits = Physics.RaycastAll(dRing, up, reach, Physics.DefaultRaycastLayers, QueryTriggerInteraction.Ignore);
            bool found = false;
            foreach (var hit in hits)
            {
                var collider = hit.collider;
                if (collider == null || IsInside(collider.transform, rig) || IsInside(collider.transform, rope)) continue;
                var attached = collider.attachedRigidbody;
                if (attached != null && attached.transform == rig) continue;
                if (found && !(hit.distance < nearest.distance)) continue; // RaycastAll's order is undefined
                nearest = hit;
                found = true;
            }
            return found;
        }

        /// <summary>
        /// Wires the rope as planned: End.Body and End.Point, and, when <see cref="RewiresStart"/>, Start onto the
        /// root-level anchor (reused when one of that name exists at the root, else created at
        /// <see cref="AnchorPosition"/>). Returns the anchor object it created (for the editor's Undo), or null.
        /// </summary>
        internal GameObject Apply()
        {
            var end = _rope.EndAttachment;
            end.Body = Body;
            end.Point = EndPoint;
            if (!RewiresStart) return null;

            GameObject created = null;
            var anchor = FindRootAnchor(AnchorName);
            if (anchor == null)
            {
                created = new GameObject(AnchorName);
                anchor = created.transform;
                anchor.position = AnchorPosition;
            }
            var start = _rope.StartAttachment;
            start.Body = null;
            start.Point = anchor;
            return created;
        }

        /// <summary>One line for the console naming what was (or would be) wired.</summary>
        /// <remarks>An anchor of that name already at the root is reused where it stands, and the line says so.</remarks>
        internal string Describe() =>
            _rope.name + ": End pulls Rigidbody '" + Body.name + "' at " + (EndPoint != null ? "'" + EndPoint.name + "'" : "its position") +
            (!RewiresStart ? "" :
             FindRootAnchor(AnchorName) != null ? "; Start anchored at the existing '" + AnchorName + "', kept where it is" :
             "; Start anchored at '" + AnchorName + "'" + (Beam != null ? ", snapped to '" + Beam.name + "'," : "") + " " +
             AnchorHeight.ToString("G4", System.Globalization.CultureInfo.InvariantCulture) + " m above it") + ".";

        /// <summary>
        /// True when <paramref name="name"/> names a D-ring: after dropping spaces, hyphens and underscores and
        /// lower-casing, it contains "dring" or "harnessattachment" ("Harness D-Ring", "D ring", "DRing_L").
        /// </summary>
        internal static bool IsDRingName(string name)
        {
            if (string.IsNullOrEmpty(name)) return false;
            var compact = new System.Text.StringBuilder(name.Length);
            foreach (char c in name)
                if (c != ' ' && c != '-' && c != '_') compact.Append(char.ToLowerInvariant(c));
            var s = compact.ToString();
            return s.Contains("dring") || s.Contains("harnessattachment");
        }

        /// <summary>The first D-ring (breadth-first) in <paramref name="rig"/>'s hierarchy outside <paramref name="excluded"/>, or null.</summary>
        static Transform FindDRing(Transform rig, Transform excluded)
        {
            var queue = new Queue<Transform>();
            queue.Enqueue(rig);
            while (queue.Count > 0)
            {
                var t = queue.Dequeue();
                if (t == excluded) continue;
                if (IsDRingName(t.name)) return t;
                for (int i = 0; i < t.childCount; i++) queue.Enqueue(t.GetChild(i));
            }
            return null;
        }

        static Transform FindRootAnchor(string name)
        {
            if (name.IndexOf('/') >= 0) return null; // Find reads '/' as a hierarchy path
            var found = GameObject.Find(name);
            return found != null && found.transform.parent == null ? found.transform : null;
        }

        /// <summary>True when <paramref name="t"/> is <paramref name="root"/> or in its hierarchy (<see cref="Transform.IsChildOf"/>); false for a null <paramref name="t"/>.</summary>
        internal static bool IsInside(Transform t, Transform root) => t != null && t.IsChildOf(root);
    }
}
