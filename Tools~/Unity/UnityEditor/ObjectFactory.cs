using System;
using HookeRope.StandIn;
using UnityEditor.SceneManagement;
using UnityEngine;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.ObjectFactory: only PlaceGameObject, which follows UCR
    /// Editor/Mono/Commands/GOCreationCommands.cs (Place), as ObjectFactory.bindings.cs forwards it there.
    /// </summary>
    public static class ObjectFactory
    {
        /// <summary>
        /// Place the given GameObject in the Scene View using the same preferences as built-in Unity GameObjects. With a
        /// <paramref name="parent"/>: it becomes the parent's child with local position zero, rotation identity, scale one
        /// and the parent's layer. Without: the object moves to the last active Scene view's pivot and then into the
        /// current stage (under the open prefab stage's root, keeping its world pose). Then its name is made unique among
        /// its siblings ("Name (1)") and it becomes the active selection. The stand-in has no "default parent" and no
        /// "Create Objects at Origin" preference (both off, as in a new Editor).
        /// </summary>
        public static void PlaceGameObject(GameObject go, GameObject parent = null)
        {
            if (go is null) throw new ArgumentNullException(nameof(go));
            if (parent != null)
            {
                var transform = go.transform;
                transform.SetParent(parent.transform, true);
                transform.localPosition = Vector3.zero;
                transform.localRotation = Quaternion.identity;
                transform.localScale = Vector3.one;
                go.layer = parent.layer;
            }
            else
            {
                SceneView.PlaceInFrontOfLastActive(go);
                StageUtility.PlaceGameObjectInCurrentStage(go);
            }
            SiblingNames.MakeUnique(go);
            Selection.activeGameObject = go;
        }
    }
}
