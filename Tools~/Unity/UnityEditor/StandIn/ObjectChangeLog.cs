using System.Collections.Generic;
using UnityEditor;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the changes ObjectChangeEvents.changesPublished will publish. Unity records every undoable
    /// change and publishes the batch once per editor update; the stand-in records two kinds, as the Scripting
    /// Reference ("ObjectChangeKind") names their sources: CreateGameObjectHierarchy from Undo.RegisterCreatedObjectUndo
    /// of a GameObject (a prefab dropped into the Hierarchy or Scene view is such a creation), ChangeGameObjectParent
    /// from Undo.SetTransformParent. PrefabUtility.InstantiatePrefab alone records nothing (it is not undoable). The
    /// batch is published at the start of the next frame of the stand-in's loop (its "editor update", in Edit and Play
    /// mode), or by <see cref="Flush"/>. Pending changes are dropped when the scene is reset.
    /// </summary>
    internal static class ObjectChangeLog
    {
        static readonly List<ObjectChangeEventStream.Event> s_Pending = new List<ObjectChangeEventStream.Event>();

        static ObjectChangeLog()
        {
            World.WorldReset += () => s_Pending.Clear();
            PlayerLoop.EditorUpdate += Flush;
        }

        /// <summary>Number of changes waiting for the next editor update.</summary>
        internal static int PendingCount => s_Pending.Count;

        internal static void RecordCreated(GameObject root) =>
            s_Pending.Add(new ObjectChangeEventStream.Event(ObjectChangeKind.CreateGameObjectHierarchy, new CreateGameObjectHierarchyEventArgs(root.GetInstanceID(), default(Scene)), default));

        internal static void RecordParentChanged(GameObject child, Transform previousParent, Transform newParent) =>
            s_Pending.Add(new ObjectChangeEventStream.Event(ObjectChangeKind.ChangeGameObjectParent, default,
                new ChangeGameObjectParentEventArgs(child.GetInstanceID(), default(Scene), IdOf(previousParent), default(Scene), IdOf(newParent))));

        /// <summary>Publishes the pending changes to ObjectChangeEvents.changesPublished (nothing when there are none); changes the subscribers record go into the next batch.</summary>
        internal static void Flush()
        {
            if (s_Pending.Count == 0) return;
            var stream = new ObjectChangeEventStream(s_Pending);
            s_Pending.Clear();
            ObjectChangeEvents.Invoke(ref stream);
        }

        static int IdOf(Transform parent) => parent == null ? 0 : parent.gameObject.GetInstanceID();
    }
}
