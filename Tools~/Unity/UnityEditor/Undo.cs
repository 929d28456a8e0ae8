using System;
using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.Undo: records operations in the stand-in's undo log (<see cref="UndoLog"/>) in undo
    /// groups; PerformUndo reverts a group of created objects (**approx.**: recorded property changes cannot be reverted,
    /// and the Editor's automatic new group per event does not exist: tests call IncrementCurrentGroup).
    /// </summary>
    public class Undo
    {
        /// <summary>Register an undo operations for a newly created object.</summary>
        public static void RegisterCreatedObjectUndo(Object objectToUndo, string name)
        {
            if (objectToUndo.GetType() == typeof(Transform) || objectToUndo.GetType().IsSubclassOf(typeof(Transform)))
                throw new ArgumentException("Cannot call 'RegisterCreatedObjectUndo' on Transform components, as transforms cannot be created/destroyed independently from their game object");
            if (objectToUndo == null) throw new ArgumentNullException(nameof(objectToUndo));
            UndoLog.Add(UndoLog.Kind.CreatedObject, objectToUndo, name);
            if (objectToUndo is GameObject created) ObjectChangeLog.RecordCreated(created);
        }

        /// <summary>Sets the parent of transform to the new parent (keeping its world pose) and records an undo operation.</summary>
        public static void SetTransformParent(Transform transform, Transform newParent, string name) =>
            SetTransformParent(transform, newParent, true, name);

        /// <summary>Sets the parent of transform to the new parent and records an undo operation (publishes ChangeGameObjectParent when the parent changed).</summary>
        public static void SetTransformParent(Transform transform, Transform newParent, bool worldPositionStays, string name)
        {
            if (transform is null) throw new ArgumentNullException(nameof(transform));
            var previous = transform.parent;
            UndoLog.Add(UndoLog.Kind.TransformParent, transform, name);
            transform.SetParent(newParent, worldPositionStays);
            if (transform.parent != previous) ObjectChangeLog.RecordParentChanged(transform.gameObject, previous, transform.parent);
        }

        /// <summary>Records any changes done on the object after the RecordObject function.</summary>
        public static void RecordObject(Object objectToUndo, string name)
        {
            if (objectToUndo == null) return;
            UndoLog.Add(UndoLog.Kind.RecordObject, objectToUndo, name);
        }

        /// <summary>Unity automatically groups undo operations by the current group index.</summary>
        public static int GetCurrentGroup() => UndoLog.CurrentGroup;

        /// <summary>Unity automatically groups undo operations by the current group index; this starts a new group.</summary>
        public static void IncrementCurrentGroup() => UndoLog.CurrentGroup++;

        /// <summary>
        /// Perform an Undo operation: reverts the latest group that has records. A created object is destroyed (with its
        /// children); a group holding a property or RecordObject record throws (the stand-in keeps no previous state).
        /// </summary>
        public static void PerformUndo()
        {
            var group = UndoLog.PopLatestGroup();
            foreach (var entry in group)
                if (entry.What != UndoLog.Kind.CreatedObject)
                    throw StandInError.Unsupported("Undo.PerformUndo of a " + entry.What + " record (the stand-in reverts created objects only)");
            foreach (var entry in group)
                if (entry.Target != null) Object.DestroyImmediate(entry.Target);
        }
    }
}
