using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Object: the base class of everything Unity references. Behaviour follows Unity 2022.3
    /// (reference source Runtime/Export/Scripting/UnityEngineObject.bindings.cs): a destroyed object compares equal to
    /// null ("fake null"), <see cref="Destroy(Object, float)"/> is deferred to the end of the frame, and
    /// <see cref="DestroyImmediate(Object, bool)"/> destroys at once.
    /// </summary>
    public partial class Object
    {
        readonly int m_InstanceID;
        string m_Name = string.Empty;
        bool m_Alive = true;

        /// <summary>Creates an object with a new (negative) instance id, as Unity does for objects made at run time.</summary>
        public Object()
        {
            m_InstanceID = World.NextInstanceId();
        }

        /// <summary>The name of the object.</summary>
        public string name
        {
            get { EnsureAlive(); return NameCore; }
            set { EnsureAlive(); NameCore = value ?? string.Empty; }
        }

        /// <summary>Should the object be hidden, saved with the Scene or modifiable by the user?</summary>
        public HideFlags hideFlags { get; set; }

        /// <summary>Gets the instance ID of the object.</summary>
        public int GetInstanceID() => m_InstanceID;

        /// <summary>Removes a GameObject, component or asset at the end of the current frame (after <paramref name="t"/> seconds).</summary>
        public static void Destroy(Object obj, float t = 0.0F)
        {
            if (obj is null || !obj.m_Alive) return;
            if (!World.IsPlaying)
            {
                Debug.LogError("Destroy may not be called from edit mode! Use DestroyImmediate instead.\n" +
                               "Destroying an object in edit mode destroys it permanently.");
                return;
            }
            if (obj is Transform transform)
            {
                Debug.LogError(TransformDestroyMessage(transform));
                return;
            }
            if (RefusesAssetDestroy(obj, false)) return;
            World.QueueDestroy(obj, t);
        }

        /// <summary>Destroys the object obj immediately. You are strongly recommended to use Destroy instead.</summary>
        public static void DestroyImmediate(Object obj, bool allowDestroyingAssets = false)
        {
            if (obj is null || !obj.m_Alive) return;
            if (obj is Transform transform)
            {
                Debug.LogError(TransformDestroyMessage(transform));
                return;
            }
            if (RefusesAssetDestroy(obj, allowDestroyingAssets)) return;
            obj.DestroyNow();
        }

        /// <summary>Does the object exist?</summary>
        public static implicit operator bool(Object exists) => !CompareBaseObjects(exists, null);

        /// <summary>Compares if two objects refer to the same.</summary>
        public static bool operator ==(Object x, Object y) => CompareBaseObjects(x, y);

        /// <summary>Compares if two objects refer to a different object.</summary>
        public static bool operator !=(Object x, Object y) => !CompareBaseObjects(x, y);

        /// <inheritdoc/>
        public override bool Equals(object other)
        {
            var otherObject = other as Object;
            if (otherObject is null && other != null) return false;
            return CompareBaseObjects(this, otherObject);
        }

        /// <inheritdoc/>
        public override int GetHashCode() => m_InstanceID;

        /// <summary>Returns the name of the object and its type, as Unity prints it.</summary>
        public override string ToString() => m_Alive ? NameCore + " (" + GetType().FullName + ")" : "null";

        // ---- stand-in internals -----------------------------------------------------------------------------
        /// <summary>False once the object has been destroyed.</summary>
        internal bool IsAlive => m_Alive;

        /// <summary>Storage of <see cref="name"/>; components forward it to their GameObject.</summary>
        internal virtual string NameCore { get => m_Name; set => m_Name = value; }

        /// <summary>Destroys the object now: GameObjects take their components and children with them.</summary>
        internal virtual void DestroyNow()
        {
            if (!m_Alive) return;
            m_Alive = false;
            OnStandInDestroy();
        }

        /// <summary>Called once when the object is really destroyed; overrides unregister and must call the base.</summary>
        internal virtual void OnStandInDestroy() { }

        /// <summary>Marks the object destroyed without any callback (used when its owner tears it down).</summary>
        internal void MarkDestroyed() => m_Alive = false;

        /// <summary>Throws Unity's MissingReferenceException when the object has been destroyed.</summary>
        internal void EnsureAlive()
        {
            if (!m_Alive)
                throw new MissingReferenceException("The object of type '" + GetType().Name +
                                                    "' has been destroyed but you are still trying to access it.");
        }

        static bool CompareBaseObjects(Object lhs, Object rhs)
        {
            bool lhsNull = lhs is null, rhsNull = rhs is null;
            if (lhsNull && rhsNull) return true;
            if (rhsNull) return !lhs.m_Alive;
            if (lhsNull) return !rhs.m_Alive;
            return lhs.m_InstanceID == rhs.m_InstanceID;
        }

        /// <summary>A loaded prefab asset (or one of its components) is destroyed only with allowDestroyingAssets; otherwise Unity's error.</summary>
        static bool RefusesAssetDestroy(Object obj, bool allowDestroyingAssets)
        {
            var go = obj as GameObject ?? (obj as Component)?.Owner;
            if (allowDestroyingAssets || go is null || !SceneHooks.IsAsset(go)) return false;
            Debug.LogError("Destroying assets is not permitted to avoid data loss.\nIf you really want to remove an asset use DestroyImmediate (theObject, true);");
            return true;
        }

        static string TransformDestroyMessage(Transform transform) =>
            "Can't destroy Transform component of '" + transform.gameObject.NameCore + "'. If you want to destroy the game object, " +
            "please call 'Destroy' on the game object instead. Destroying the transform component is not allowed.";
    }
}
