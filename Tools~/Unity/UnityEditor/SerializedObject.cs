using System;
using System.Collections.Generic;
using System.Reflection;
using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.SerializedObject: edits the serialized fields of scripts (MonoBehaviour,
    /// ScriptableObject) generically. As in Unity it works on its own copy of the serialized data: properties read
    /// and write the copy, <see cref="Update"/> re-reads the targets (dropping unapplied edits) and
    /// <see cref="ApplyModifiedProperties"/> writes the edited values back, records Undo and sends OnValidate to
    /// each target (the Editor calls OnValidate "when a value changes in the Inspector", which is this path).
    /// Built-in components (Transform, Rigidbody …) keep their data natively and are outside the stand-in.
    /// </summary>
    public class SerializedObject : IDisposable
    {
        readonly Object[] m_Targets;
        readonly Type m_Type;
        SerializedSnapshot[] m_Snapshots;
        readonly List<SerializedPath> m_Modified = new List<SerializedPath>();

        /// <summary>Create SerializedObject for inspected object.</summary>
        public SerializedObject(Object obj) : this(new[] { obj }) { }

        /// <summary>Create SerializedObject for inspected objects (multi-object editing).</summary>
        public SerializedObject(Object[] objs)
        {
            if (objs == null) throw new ArgumentNullException(nameof(objs));
            if (objs.Length == 0) throw new ArgumentException("SerializedObject needs at least one object", nameof(objs));
            for (int i = 0; i < objs.Length; i++)
                if (objs[i] == null) throw new ArgumentException("Object at index " + i + " is null");
            m_Type = objs[0].GetType();
            if (!(objs[0] is MonoBehaviour) && !(objs[0] is ScriptableObject))
                throw StandInError.Unsupported("SerializedObject of a " + m_Type.FullName + " (the stand-in edits MonoBehaviour and ScriptableObject fields only)");
            foreach (var o in objs)
                if (o.GetType() != m_Type) throw StandInError.Unsupported("SerializedObject over objects of different types");
            m_Targets = (Object[])objs.Clone();
            Update();
        }

        /// <summary>The inspected object (Read Only).</summary>
        public Object targetObject => m_Targets[0];

        /// <summary>The inspected objects (Read Only).</summary>
        public Object[] targetObjects => (Object[])m_Targets.Clone();

        /// <summary>Does the serialized object represents multiple objects due to multi-object editing? (Read Only)</summary>
        public bool isEditingMultipleObjects => m_Targets.Length > 1;

        /// <summary>Does it have any modified properties that have not been applied?</summary>
        public bool hasModifiedProperties => m_Modified.Count > 0;

        /// <summary>Update serialized object's representation (re-reads the targets; unapplied edits are dropped).</summary>
        public void Update()
        {
            m_Snapshots = new SerializedSnapshot[m_Targets.Length];
            for (int i = 0; i < m_Targets.Length; i++) m_Snapshots[i] = new SerializedSnapshot(m_Targets[i]);
            m_Modified.Clear();
        }

        /// <summary>Find serialized property by name (null when there is none).</summary>
        public SerializedProperty FindProperty(string propertyPath)
        {
            var path = SerializedPath.Resolve(m_Type, propertyPath);
            if (path == null || !SerializedValues.Exists(m_Snapshots[0], path.Steps)) return null;
            return new SerializedProperty(this, path);
        }

        /// <summary>Apply property modifications (records Undo, then sends OnValidate to the targets).</summary>
        public bool ApplyModifiedProperties() => Apply(withUndo: true);

        /// <summary>Applies property modifications without registering an undo operation.</summary>
        public bool ApplyModifiedPropertiesWithoutUndo() => Apply(withUndo: false);

        /// <summary>Releases the serialized object (nothing to release in the stand-in).</summary>
        public void Dispose() { }

        // ---- stand-in internals -----------------------------------------------------------------------------
        internal int TargetCount => m_Targets.Length;

        /// <summary>The value at <paramref name="path"/> in target <paramref name="index"/>'s copy.</summary>
        internal object Read(SerializedPath path, int index) => SerializedValues.Get(m_Snapshots[index], path.Steps);

        /// <summary>True when target <paramref name="index"/>'s copy has <paramref name="path"/> (array lengths may differ).</summary>
        internal bool Has(SerializedPath path, int index) => SerializedValues.Exists(m_Snapshots[index], path.Steps);

        /// <summary>Writes <paramref name="value"/> at <paramref name="path"/> into every target's copy; marks the path modified when a value changed.</summary>
        internal void Write(SerializedPath path, object value)
        {
            bool changed = false;
            for (int i = 0; i < m_Snapshots.Length; i++)
            {
                if (!Has(path, i)) continue;
                if (SerializedValues.DeepEquals(Read(path, i), value, path.Slot.Type)) continue;
                SerializedValues.Set(m_Snapshots[i], path.Steps, value);
                changed = true;
            }
            if (!changed) return;
            foreach (var modified in m_Modified)
                if (modified.Path == path.Path) return;
            m_Modified.Add(path);
        }

        /// <summary>The path <paramref name="propertyPath"/> of this object's type, or null.</summary>
        internal SerializedPath Resolve(string propertyPath) => SerializedPath.Resolve(m_Type, propertyPath);

        bool Apply(bool withUndo)
        {
            if (m_Modified.Count == 0) return false;
            var names = new List<string>();
            foreach (var path in m_Modified) names.Add(path.Path);
            for (int i = 0; i < m_Targets.Length; i++)
            {
                var target = m_Targets[i];
                if (target == null) continue;
                if (withUndo) UndoLog.Add(UndoLog.Kind.ModifiedProperties, target, "Modified " + string.Join(", ", names) + " in " + target.name);
                foreach (var path in m_Modified)
                {
                    if (!Has(path, i)) continue;
                    var value = SerializedCopy.CopyValue(Read(path, i), path.Slot.Type);
                    SerializedValues.Set(target, path.Steps, value);
                }
            }
            m_Modified.Clear();
            for (int i = 0; i < m_Targets.Length; i++)
                if (m_Targets[i] != null) SendOnValidate(m_Targets[i]);
            return true;
        }

        static void SendOnValidate(Object target)
        {
            if (target is MonoBehaviour behaviour)
            {
                Messages.Send(behaviour, "OnValidate");
                return;
            }
            MethodInfo method = null;
            const BindingFlags Declared = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly;
            for (var t = target.GetType(); t != null && t != typeof(ScriptableObject) && method == null; t = t.BaseType)
                method = t.GetMethod("OnValidate", Declared, null, Type.EmptyTypes, null);
            if (method == null) return;
            try
            {
                method.Invoke(target, null);
            }
            catch (TargetInvocationException e)
            {
                Debug.LogException(e.InnerException ?? e, target);
            }
        }
    }
}
