using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// The editor hook that wires a rope the moment it lands on a harness rig in Edit mode: a prefab dropped into the
    /// Hierarchy or Scene view under a rig (an undoable creation: ObjectChangeKind.CreateGameObjectHierarchy) or an
    /// existing rope dragged under one (Undo.SetTransformParent: ObjectChangeKind.ChangeGameObjectParent). Unity
    /// publishes these changes batched, once per editor update, through ObjectChangeEvents.changesPublished. Every
    /// ElasticRope in the created or re-parented hierarchy that sits under a Rigidbody, whose End has no Body yet and
    /// that <see cref="RopeAutoWiring.For"/> would change is wired like the inspector's fix (<see cref="RopeAttachFix.Apply(ElasticRope, RopeAutoWiring, string)"/>:
    /// Undo on the rope and on a created anchor) and logs one line (<see cref="RopeAutoWiring.Describe"/>).
    /// Left alone: ropes whose End.Body the user set; everything in Play mode (Awake wires a dropped rope there, once);
    /// and, inside an open prefab stage, a rope whose wiring would create or reuse a root-level anchor: the rig is in
    /// the stage, but a new GameObject goes to the main scene, and a prefab cannot keep a reference to it, so that rope
    /// keeps the inspector's HelpBox and its one-click fix instead (End-only wiring, onto a rig in the same stage, is done).
    /// </summary>
    [InitializeOnLoad]
    internal static class RopeDropWiring
    {
        /// <summary>The Undo name of the hook's wiring.</summary>
        internal const string UndoName = "Wire Rope onto Rig";

        static RopeDropWiring()
        {
            ObjectChangeEvents.changesPublished += OnChangesPublished;
        }

        static void OnChangesPublished(ref ObjectChangeEventStream stream)
        {
            if (EditorApplication.isPlaying) return; // Awake wires dropped ropes in Play
            for (int i = 0; i < stream.length; i++)
            {
                int instanceId;
                switch (stream.GetEventType(i))
                {
                    case ObjectChangeKind.CreateGameObjectHierarchy:
                        stream.GetCreateGameObjectHierarchyEvent(i, out var created);
                        instanceId = created.instanceId;
                        break;
                    case ObjectChangeKind.ChangeGameObjectParent:
                        stream.GetChangeGameObjectParentEvent(i, out var reparented);
                        instanceId = reparented.instanceId;
                        break;
                    default:
                        continue;
                }
                WireHierarchy(EditorUtility.InstanceIDToObject(instanceId) as GameObject);
            }
        }

        /// <summary>Wires every rope in <paramref name="root"/>'s hierarchy (inactive ones included) that <see cref="Wire"/> accepts; returns how many it wired.</summary>
        internal static int WireHierarchy(GameObject root)
        {
            if (root == null) return 0;
            int wired = 0;
            foreach (var rope in root.GetComponentsInChildren<ElasticRope>(true))
                if (Wire(rope)) wired++;
            return wired;
        }

        /// <summary>
        /// Wires <paramref name="rope"/> onto the Rigidbody above it, with Undo and one console line, when its End has no
        /// Body, the plan changes something and (in a prefab stage) needs no root-level anchor; true when it did.
        /// </summary>
        internal static bool Wire(ElasticRope rope)
        {
            var wiring = RopeAutoWiring.ForDrop(rope);
            if (wiring == null) return false;
            if (wiring.RewiresStart && InOpenPrefabStage(rope.transform)) return false;
            string line = wiring.WiredLine(); // before Apply: afterwards the new anchor reads as an existing one
            RopeAttachFix.Apply(rope, wiring, UndoName);
            Debug.Log(line, rope);
            return true;
        }

        static bool InOpenPrefabStage(Transform t)
        {
            var stage = PrefabStageUtility.GetCurrentPrefabStage();
            return stage != null && RopeAutoWiring.IsInside(t, stage.prefabContentsRoot.transform);
        }
    }
}
