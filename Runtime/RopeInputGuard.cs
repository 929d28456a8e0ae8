using System.Globalization;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// Checks what reaches a rope from the scene (attachments destroyed during Play, non-finite poses, unusable
    /// Rigidbody masses, transforms that cannot be inverted) and reports each problem once: one console warning per
    /// cause, naming the component's object and the field, again only after the cause has cleared and come back.
    /// The checks are allocation-free while everything is valid; a message is composed only when it is logged.
    /// Documentation~/index.md, "Bad input", lists the cases and what the rope does in each.
    /// </summary>
    internal sealed class RopeInputGuard
    {
        /// <summary>The start end's slot (Start.Point, Start.Body).</summary>
        public const int Start = 0;

        /// <summary>The end end's slot (End.Point, End.Body).</summary>
        public const int End = 1;

        // cause bits: four per slot (slot · 4 + cause), then the renderer's
        const int PointDestroyed = 0, BodyDestroyed = 1, Pose = 2, Mass = 3;
        const int ScaleBit = 1 << 8, MeshPositionsBit = 1 << 9, StepCostBit = 1 << 10;

        /// <summary>Consecutive over-budget steps before the step cost is reported (the first steps pay for JIT compilation).</summary>
        const int OverBudgetSteps = 3;

        readonly Object _context;
        readonly string _component;
        int _reported, _overBudget;

        // the attachments the rope was built with: reference and name (a destroyed object has no readable name)
        readonly Transform[] _points = new Transform[2];
        readonly Rigidbody[] _bodies = new Rigidbody[2];
        readonly string[] _pointNames = new string[2], _bodyNames = new string[2];

        /// <summary>A guard reporting on <paramref name="context"/>, a component of type <paramref name="component"/> (its name in messages).</summary>
        public RopeInputGuard(Object context, string component)
        {
            _context = context;
            _component = component;
        }

        /// <summary>
        /// After a build: remembers the live attachments of both ends (and their names, for the message when one is
        /// destroyed) and forgets the destroyed-attachment reports. Allocates the names (a build allocates anyway).
        /// </summary>
        public void RecordAttachments(RopeEnd start, RopeEnd end)
        {
            Record(Start, start);
            Record(End, end);
        }

        void Record(int slot, RopeEnd end)
        {
            _points[slot] = end.Point != null ? end.Point : null;
            _bodies[slot] = end.Body != null ? end.Body : null;
            _pointNames[slot] = _points[slot] != null ? _points[slot].name : null;
            _bodyNames[slot] = _bodies[slot] != null ? _bodies[slot].name : null;
            Clear(Bit(slot, PointDestroyed));
            Clear(Bit(slot, BodyDestroyed));
        }

        /// <summary>
        /// True when the Point or Body that end <paramref name="slot"/> was built with has been destroyed since (the
        /// field still holds it, and it compares equal to null): logs one warning naming the rope and the field and
        /// forgets the object, so the next call returns false. The caller then re-attaches the end to what is left.
        /// Allocation-free when nothing was destroyed.
        /// </summary>
        public bool TakeDestroyed(int slot, RopeEnd end)
        {
            bool pointLost = IsDestroyed(_points[slot], end.Point);
            bool bodyLost = IsDestroyed(_bodies[slot], end.Body);
            if (!pointLost && !bodyLost) return false;
            string field = SlotName(slot);
            string left = end.Kind == RopeEndKind.Transform
                ? "it now follows " + field + ".Point ('" + _pointNames[slot] + "') as a Transform end"
                : "it now hangs free";
            if (bodyLost)
                Warn(Bit(slot, BodyDestroyed), field + ".Body ('" + _bodyNames[slot] + "') was destroyed; its mass left the rope and " + left +
                     ". Assign " + field + ".Body again to re-attach it.");
            else
                Warn(Bit(slot, PointDestroyed), field + ".Point ('" + _pointNames[slot] + "') was destroyed; " + left +
                     ". Assign " + field + ".Point again to re-attach it.");
            if (pointLost) _points[slot] = null;
            if (bodyLost) _bodies[slot] = null;
            return true;
        }

        static bool IsDestroyed(Object recorded, Object current) =>
            !ReferenceEquals(recorded, null) && ReferenceEquals(recorded, current) && current == null;

        /// <summary>
        /// True when <paramref name="position"/> (the world pose of end <paramref name="slot"/>, m) is finite. Otherwise
        /// logs one warning naming the rope, the field and the object (until the pose is finite again) and returns
        /// false: the caller keeps the end's last pose. Allocation-free while the pose is finite.
        /// </summary>
        public bool AcceptPose(int slot, RopeEnd end, Vector3 position)
        {
            int bit = Bit(slot, Pose);
            if (IsFinite(position))
            {
                Clear(bit);
                return true;
            }
            if (!IsReported(bit))
            {
                string field = SlotName(slot) + (end.Body != null ? ".Body" : ".Point");
                Object source = end.Body != null ? (Object)end.Body : end.Point;
                Warn(bit, field + " ('" + source.name + "') is at a non-finite position " + Format(position) +
                          "; the rope keeps the end's last valid pose until it is finite again.");
            }
            return false;
        }

        /// <summary>
        /// True when <paramref name="body"/>'s mass is finite and positive, so the rope can load end <paramref name="slot"/>
        /// with it. Otherwise logs one warning naming the rope, the body and Rigidbody.mass and returns false: the
        /// caller pins the end to the body instead (kinematic: the rope follows the body and does not pull it).
        /// </summary>
        public bool AcceptMass(int slot, Rigidbody body)
        {
            int bit = Bit(slot, Mass);
            float mass = body.mass;
            if (float.IsFinite(mass) && mass > 0f)
            {
                Clear(bit);
                return true;
            }
            Warn(bit, SlotName(slot) + ".Body ('" + body.name + "') has Rigidbody.mass = " + mass.ToString(CultureInfo.InvariantCulture) +
                      " kg (must be finite and > 0); the end follows the body as a kinematic pin and does not pull it until the rope is rebuilt with a valid mass.");
            return false;
        }

        /// <summary>
        /// True when <paramref name="frame"/> can take world points into its local space: every component of its
        /// lossyScale is finite and non-zero. Otherwise logs one warning naming the object and Transform scale (until
        /// the scale is valid again) and returns false: the renderer keeps the mesh it last uploaded.
        /// </summary>
        public bool AcceptDrawingFrame(Transform frame)
        {
            Vector3 scale = frame.lossyScale;
            bool valid = IsInvertible(scale.x) && IsInvertible(scale.y) && IsInvertible(scale.z);
            if (valid)
            {
                Clear(ScaleBit);
                return true;
            }
            Warn(ScaleBit, "Transform scale " + Format(scale) + " (lossyScale of '" + frame.name +
                           "' and its parents) cannot be inverted, so the rope cannot be drawn in its local space; the mesh keeps its last frame until the scale is non-zero.");
            return false;
        }

        /// <summary>
        /// True when the first <paramref name="count"/> positions in <paramref name="x"/>, <paramref name="y"/>,
        /// <paramref name="z"/> (the mesh's input, m) are finite. Otherwise logs one warning (until they are finite
        /// again) and returns false: the renderer keeps the mesh it last uploaded. Allocation-free.
        /// </summary>
        public bool AcceptMeshPositions(float[] x, float[] y, float[] z, int count)
        {
            for (int i = 0; i < count; i++)
            {
                if (float.IsFinite(x[i]) && float.IsFinite(y[i]) && float.IsFinite(z[i])) continue;
                Warn(MeshPositionsBit, "particle " + i.ToString(CultureInfo.InvariantCulture) + " is at a non-finite position (" +
                                       Format(new Vector3(x[i], y[i], z[i])) + " in local space); the mesh keeps its last valid frame.");
                return false;
            }
            Clear(MeshPositionsBit);
            return true;
        }

        /// <summary>
        /// Watches the real time a step costs: when <paramref name="stepMilliseconds"/> exceeds the simulated
        /// <paramref name="deltaTime"/> (s) for <see cref="OverBudgetSteps"/> steps in a row, Unity's fixed-step loop
        /// falls further behind every frame; logs one warning naming the rope and the fields that set the cost
        /// (until the steps fit again). A valid but huge Segment count (the table allows 10 000) ends here.
        /// </summary>
        public void WatchStepCost(float stepMilliseconds, float deltaTime, int segments, int substeps, int iterations)
        {
            if (stepMilliseconds <= deltaTime * 1000f)
            {
                _overBudget = 0;
                Clear(StepCostBit);
                return;
            }
            if (++_overBudget < OverBudgetSteps || IsReported(StepCostBit)) return;
            var c = CultureInfo.InvariantCulture;
            Warn(StepCostBit, "one step of " + deltaTime.ToString(c) + " s took " + stepMilliseconds.ToString("0.#", c) + " ms of real time (Segment count = " +
                              segments.ToString(c) + ", Substeps = " + substeps.ToString(c) + ", Iterations = " + iterations.ToString(c) +
                              "), so the physics loop falls behind and the frame rate collapses; lower Segment count, Substeps or Iterations.");
        }

        static bool IsInvertible(float scale) => float.IsFinite(scale) && scale != 0f && float.IsFinite(1f / scale);

        static bool IsFinite(Vector3 v) => float.IsFinite(v.x) && float.IsFinite(v.y) && float.IsFinite(v.z);

        static int Bit(int slot, int cause) => 1 << (slot * 4 + cause);

        static string SlotName(int slot) => slot == Start ? "Start" : "End";

        bool IsReported(int bit) => (_reported & bit) != 0;

        void Clear(int bit) => _reported &= ~bit;

        /// <summary>Logs <paramref name="message"/> unless cause <paramref name="bit"/> is already reported.</summary>
        void Warn(int bit, string message)
        {
            if (IsReported(bit)) return;
            _reported |= bit;
            Debug.LogWarning(_component + " '" + (_context != null ? _context.name : "?") + "': " + message, _context);
        }

        static string Format(Vector3 v) =>
            "(" + v.x.ToString(CultureInfo.InvariantCulture) + ", " + v.y.ToString(CultureInfo.InvariantCulture) + ", " +
            v.z.ToString(CultureInfo.InvariantCulture) + ")";
    }
}
