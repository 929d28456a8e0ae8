using UnityEngine;

namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.GameObjectUtility: GameObject utility functions (reference source Editor/Mono/GameObjectUtility.bindings.cs).</summary>
    public sealed class GameObjectUtility
    {
        /// <summary>
        /// Sets the parent and gives the child the same layer and position: nothing when parent is null; otherwise the
        /// child becomes a child of parent with local position zero, local rotation identity, local scale one, and it
        /// and its descendants take the parent's layer.
        /// </summary>
        public static void SetParentAndAlign(GameObject child, GameObject parent)
        {
            if (parent == null) return;
            child.transform.SetParent(parent.transform, false);
            child.transform.localPosition = Vector3.zero;
            child.transform.localRotation = Quaternion.identity;
            child.transform.localScale = Vector3.one;
            SetLayerRecursively(child, parent.layer);
        }

        static void SetLayerRecursively(GameObject go, int layer)
        {
            go.layer = layer;
            foreach (Transform child in go.transform) SetLayerRecursively(child.gameObject, layer);
        }
    }
}
