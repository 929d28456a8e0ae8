using System;
using System.Collections;
using System.Collections.Generic;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Transform: position, rotation and scale in a parent hierarchy. World space composes
    /// translation · rotation · scale from the root down (p_world = parent.TransformPoint(localPosition +
    /// localRotation · (localScale ∘ p))), as Unity's localToWorldMatrix does; lossyScale is the diagonal of the
    /// world rotation-and-scale matrix with the world rotation taken out, as Unity documents ("lossy" under skew).
    /// Allocation-free.
    /// </summary>
    public class Transform : Component, IEnumerable
    {
        Vector3 m_LocalPosition;
        Quaternion m_LocalRotation = Quaternion.identity;
        Vector3 m_LocalScale = Vector3.one;
        Transform m_Parent;
        readonly List<Transform> m_Children = new List<Transform>();

        /// <summary>Created by GameObject only.</summary>
        protected Transform() { }

        /// <summary>The world space position of the Transform.</summary>
        public Vector3 position
        {
            get { EnsureAlive(); return m_Parent is null ? m_LocalPosition : m_Parent.TransformPoint(m_LocalPosition); }
            set
            {
                EnsureAlive();
                if (RejectsNonFinite("position", "position", value.x, value.y, value.z)) return;
                m_LocalPosition = m_Parent is null ? value : m_Parent.InverseTransformPoint(value);
            }
        }

        /// <summary>A Quaternion that stores the rotation of the Transform in world space.</summary>
        public Quaternion rotation
        {
            get { EnsureAlive(); return m_Parent is null ? m_LocalRotation : m_Parent.rotation * m_LocalRotation; }
            set
            {
                EnsureAlive();
                if (RejectsNonFinite("rotation", "rotation", value.x, value.y, value.z, value.w)) return;
                m_LocalRotation = Quaternion.Normalize(m_Parent is null ? value : Quaternion.Inverse(m_Parent.rotation) * value);
            }
        }

        /// <summary>Position of the transform relative to the parent transform.</summary>
        public Vector3 localPosition
        {
            get { EnsureAlive(); return m_LocalPosition; }
            set
            {
                EnsureAlive();
                if (RejectsNonFinite("localPosition", "localPosition", value.x, value.y, value.z)) return;
                m_LocalPosition = value;
            }
        }

        /// <summary>The rotation of the transform relative to the transform rotation of the parent.</summary>
        public Quaternion localRotation
        {
            get { EnsureAlive(); return m_LocalRotation; }
            set
            {
                EnsureAlive();
                if (RejectsNonFinite("localRotation", "rotation", value.x, value.y, value.z, value.w)) return;
                m_LocalRotation = Quaternion.Normalize(value);
            }
        }

        /// <summary>The scale of the transform relative to the GameObjects parent.</summary>
        public Vector3 localScale
        {
            get { EnsureAlive(); return m_LocalScale; }
            set { EnsureAlive(); m_LocalScale = value; }
        }

        /// <summary>The global scale of the object (Read Only).</summary>
        public Vector3 lossyScale
        {
            get
            {
                EnsureAlive();
                if (m_Parent is null) return m_LocalScale;
                var inverse = Quaternion.Inverse(rotation);
                return new Vector3(
                    (inverse * TransformVector(new Vector3(1f, 0f, 0f))).x,
                    (inverse * TransformVector(new Vector3(0f, 1f, 0f))).y,
                    (inverse * TransformVector(new Vector3(0f, 0f, 1f))).z);
            }
        }

        /// <summary>The red axis of the transform in world space.</summary>
        public Vector3 right => rotation * Vector3.right;

        /// <summary>The green axis of the transform in world space.</summary>
        public Vector3 up => rotation * Vector3.up;

        /// <summary>Returns a normalized vector representing the blue axis of the transform in world space.</summary>
        public Vector3 forward => rotation * Vector3.forward;

        /// <summary>The parent of the transform (setting it keeps the world pose, as SetParent(parent, true)).</summary>
        public Transform parent
        {
            get { EnsureAlive(); return m_Parent; }
            set => SetParent(value, true);
        }

        /// <summary>Returns the topmost transform in the hierarchy.</summary>
        public Transform root
        {
            get
            {
                EnsureAlive();
                var t = this;
                while (t.m_Parent is object) t = t.m_Parent;
                return t;
            }
        }

        /// <summary>The number of children the parent Transform has.</summary>
        public int childCount
        {
            get { EnsureAlive(); return m_Children.Count; }
        }

        /// <summary>Is this transform a child of parent? True for a child, a deep child, or the transform itself (Unity's Internal_IsChildOrSameTransform; parent must not be null).</summary>
        public bool IsChildOf(Transform parent)
        {
            EnsureAlive();
            if (parent is null) throw new ArgumentNullException(nameof(parent));
            for (var t = this; t is object; t = t.m_Parent)
                if (ReferenceEquals(t, parent)) return true;
            return false;
        }

        /// <summary>Returns a transform child by index.</summary>
        public Transform GetChild(int index)
        {
            EnsureAlive();
            if (index < 0 || index >= m_Children.Count) throw new UnityException("Transform child out of bounds");
            return m_Children[index];
        }

        /// <summary>Set the parent of the transform (world pose kept).</summary>
        public void SetParent(Transform p) => SetParent(p, true);

        /// <summary>Set the parent of the transform; worldPositionStays keeps the world position, rotation and scale.</summary>
        public void SetParent(Transform parent, bool worldPositionStays)
        {
            EnsureAlive();
            if (ReferenceEquals(parent, m_Parent)) return;
            if (parent is object)
            {
                parent.EnsureAlive();
                for (var t = parent; t is object; t = t.m_Parent)
                {
                    if (!ReferenceEquals(t, this)) continue;
                    Debug.LogError("Cannot set the parent of the GameObject '" + gameObject.NameCore + "' to itself or one of its children.");
                    return;
                }
            }
            bool wasActive = Owner.IsActiveInHierarchy;
            Vector3 worldPosition = position, worldScale = lossyScale;
            Quaternion worldRotation = rotation;

            m_Parent?.m_Children.Remove(this);
            m_Parent = parent;
            m_Parent?.m_Children.Add(this);

            if (worldPositionStays)
            {
                position = worldPosition;
                rotation = worldRotation;
                var parentScale = m_Parent is null ? Vector3.one : m_Parent.lossyScale;
                m_LocalScale = new Vector3(SafeDivide(worldScale.x, parentScale.x), SafeDivide(worldScale.y, parentScale.y), SafeDivide(worldScale.z, parentScale.z));
            }
            bool isActive = Owner.IsActiveInHierarchy;
            if (wasActive != isActive) Lifecycle.ActiveInHierarchyChanged(Owner, isActive);
        }

        /// <summary>Sets the world space position and rotation of the Transform component.</summary>
        public void SetPositionAndRotation(Vector3 position, Quaternion rotation)
        {
            this.position = position;
            this.rotation = rotation;
        }

        /// <summary>Transforms position from local space to world space.</summary>
        public Vector3 TransformPoint(Vector3 position)
        {
            EnsureAlive();
            var p = m_LocalPosition + m_LocalRotation * Vector3.Scale(m_LocalScale, position);
            return m_Parent is null ? p : m_Parent.TransformPoint(p);
        }

        /// <summary>Transforms vector from local space to world space. This operation is affected by scale.</summary>
        public Vector3 TransformVector(Vector3 vector)
        {
            EnsureAlive();
            var v = m_LocalRotation * Vector3.Scale(m_LocalScale, vector);
            return m_Parent is null ? v : m_Parent.TransformVector(v);
        }

        /// <summary>Transforms direction from local space to world space. This operation is not affected by scale or position.</summary>
        public Vector3 TransformDirection(Vector3 direction) => rotation * direction;

        /// <summary>Transforms position from world space to local space.</summary>
        public Vector3 InverseTransformPoint(Vector3 position)
        {
            EnsureAlive();
            var p = m_Parent is null ? position : m_Parent.InverseTransformPoint(position);
            return DivideByScale(Quaternion.Inverse(m_LocalRotation) * (p - m_LocalPosition));
        }

        /// <summary>Transforms vector from world space to local space. This operation is affected by scale.</summary>
        public Vector3 InverseTransformVector(Vector3 vector)
        {
            EnsureAlive();
            var v = m_Parent is null ? vector : m_Parent.InverseTransformVector(vector);
            return DivideByScale(Quaternion.Inverse(m_LocalRotation) * v);
        }

        /// <summary>Transforms a direction from world space to local space. This operation is unaffected by scale.</summary>
        public Vector3 InverseTransformDirection(Vector3 direction) => Quaternion.Inverse(rotation) * direction;

        /// <summary>Enumerates the children.</summary>
        public IEnumerator GetEnumerator()
        {
            EnsureAlive();
            return m_Children.ToArray().GetEnumerator();
        }

        // ---- stand-in internals -----------------------------------------------------------------------------
        internal List<Transform> ChildList => m_Children;

        internal Transform ParentCore => m_Parent;

        /// <summary>Leaves the parent without touching the local pose (the object is being destroyed).</summary>
        internal void DetachFromParent()
        {
            m_Parent?.m_Children.Remove(this);
            m_Parent = null;
        }

        Vector3 DivideByScale(Vector3 v) =>
            new Vector3(SafeDivide(v.x, m_LocalScale.x), SafeDivide(v.y, m_LocalScale.y), SafeDivide(v.z, m_LocalScale.z));

        /// <summary>
        /// Unity's refusal of a non-finite pose: logs "transform.position assign attempt for 'X' is not valid. Input
        /// position is { NaN, 0.000000, 0.000000 }." and keeps the old value (true). False when every value is finite.
        /// </summary>
        bool RejectsNonFinite(string member, string input, float x, float y, float z, float w = 0f)
        {
            if (float.IsFinite(x) && float.IsFinite(y) && float.IsFinite(z) && float.IsFinite(w)) return false;
            bool quaternion = input == "rotation";
            Debug.LogError("transform." + member + " assign attempt for '" + NameCore + "' is not valid. Input " + input + " is { " +
                           Number(x) + ", " + Number(y) + ", " + Number(z) + (quaternion ? ", " + Number(w) : "") + " }.", this);
            return true;
        }

        static string Number(float v) => float.IsNaN(v) ? "NaN" : v.ToString("F6", System.Globalization.CultureInfo.InvariantCulture);

        /// <summary>A zero scale axis maps back to 0 (the stand-in's approximation of Unity's inverse of a singular matrix).</summary>
        static float SafeDivide(float a, float b) => b == 0f ? 0f : a / b;
    }
}
