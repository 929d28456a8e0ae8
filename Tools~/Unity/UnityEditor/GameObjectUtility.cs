using UnityEngine;

namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.GameObjectUtility: GameObject utility functions.</summary>
    public sealed class GameObjectUtility
    {
        /// <summary>Sets the parent and gives the child the same layer and position.</summary>
        public static void SetParentAndAlign(GameObject child, GameObject parent) => throw Shim.NotRun;
    }
}
