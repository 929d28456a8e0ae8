using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Collider: the base class of all colliders. The physics engine keeps its own copy of a
    /// collider's Transform (Physics.autoSyncTransforms off, Unity's default since 2018.3): taken when the collider is
    /// added or re-enabled and at the start of every physics step (or Physics.SyncTransforms); a collider attached to a
    /// Rigidbody moves with the body's pose instead. Queries and contact checks see that copy, as in Unity.
    /// </summary>
    public class Collider : Component
    {
        bool m_Enabled = true;
        bool m_IsTrigger;
        ShapeFrame m_SyncedFrame;
        bool m_SyncedInScene;

        /// <summary>Enabled Colliders will collide with other Colliders, disabled Colliders won't.</summary>
        public bool enabled
        {
            get { EnsureAlive(); return m_Enabled; }
            set
            {
                EnsureAlive();
                if (value == m_Enabled) return;
                m_Enabled = value;
                if (value) SyncTransform();
            }
        }

        /// <summary>The rigidbody the collider is attached to: the Rigidbody on its GameObject or the nearest one on a parent.</summary>
        public Rigidbody attachedRigidbody
        {
            get
            {
                EnsureAlive();
                for (var t = transform; t is object; t = t.parent)
                {
                    var body = t.GetComponent<Rigidbody>();
                    if (body is object) return body;
                }
                return null;
            }
        }

        /// <summary>Specify if this collider is configured as a trigger.</summary>
        public bool isTrigger
        {
            get { EnsureAlive(); return m_IsTrigger; }
            set { EnsureAlive(); m_IsTrigger = value; }
        }

        // ---- stand-in internals -----------------------------------------------------------------------------

        internal override void OnStandInAttached()
        {
            base.OnStandInAttached();
            if (GetType() == typeof(Collider))
                throw StandInError.Unsupported("AddComponent<Collider>() (Collider is abstract in Unity: add a SphereCollider, BoxCollider, CapsuleCollider or MeshCollider)");
            SyncTransform();
            PhysicsWorld.Add(this);
        }

        internal override void OnStandInDestroy()
        {
            PhysicsWorld.Remove(this);
            base.OnStandInDestroy();
        }

        /// <summary>In the physics scene: alive, enabled and on an active GameObject.</summary>
        internal bool InScene => IsAlive && m_Enabled && Owner.IsActiveInHierarchy;

        /// <summary>Copies the Transform into the physics engine's view of this collider (Physics.SyncTransforms).</summary>
        internal void SyncTransform()
        {
            m_SyncedFrame = ShapeFrame.Of(transform);
            m_SyncedInScene = InScene;
        }

        /// <summary>A collider that (re)joined the scene since the last sync enters it where its Transform is now, as Unity re-adds its shape.</summary>
        internal void SyncIfRejoined()
        {
            bool inScene = InScene;
            if (inScene && !m_SyncedInScene) m_SyncedFrame = ShapeFrame.Of(transform);
            m_SyncedInScene = inScene;
        }

        /// <summary>The collider's frame in the frame of <paramref name="body"/>'s Transform (no scale), from the Transforms now.</summary>
        internal ShapeFrame FrameInBody(Rigidbody body)
        {
            var own = transform;
            var bodyTransform = body.transform;
            if (ReferenceEquals(own, bodyTransform)) return new ShapeFrame(Vector3.zero, Quaternion.identity, own.lossyScale);
            var inverse = Quaternion.Inverse(bodyTransform.rotation);
            return new ShapeFrame(inverse * (own.position - bodyTransform.position), inverse * own.rotation, own.lossyScale);
        }

        /// <summary>The collider's frame as the physics engine has it: its body's pose, or its last synced Transform.</summary>
        internal ShapeFrame PhysicsFrame(Rigidbody body)
        {
            if (body is null || !body.IsAlive) return m_SyncedFrame;
            var local = FrameInBody(body);
            var rotation = body.PhysicsRotation;
            return new ShapeFrame(body.PhysicsPosition + rotation * local.Position, rotation * local.Rotation, local.Scale);
        }

        /// <summary>The collider's geometry in world space as the physics engine has it.</summary>
        internal WorldShape PhysicsShape(Rigidbody body) => BuildShape(PhysicsFrame(body));

        /// <summary>The collider's geometry laid out in <paramref name="frame"/>.</summary>
        internal virtual WorldShape BuildShape(in ShapeFrame frame) => throw StandInError.Unsupported(GetType().Name + " geometry");

        /// <summary>What the stand-in cannot test about this collider (see <see cref="ShapeKind.Unsupported"/>).</summary>
        internal virtual string UnsupportedGeometry() => GetType().Name + " " + Describe();

        /// <summary>"'name' (Type)" for messages.</summary>
        internal string Describe() => "'" + NameCore + "' (" + GetType().Name + ")";
    }
}
