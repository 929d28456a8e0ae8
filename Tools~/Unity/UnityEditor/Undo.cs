using System;
using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.Undo: records operations in the stand-in's undo log (<see cref="UndoLog"/>); nothing
    /// can be undone (the stand-in has no Edit &gt; Undo).
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
        }

        /// <summary>Records any changes done on the object after the RecordObject function.</summary>
        public static void RecordObject(Object objectToUndo, string name)
        {
            if (objectToUndo == null) return;
            UndoLog.Add(UndoLog.Kind.RecordObject, objectToUndo, name);
        }
    }
}
