using System;
using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor.SceneManagement
{
    /// <summary>
    /// Stand-in of UnityEditor.SceneManagement.PrefabStageUtility (UCR …/StageManager/PrefabStage/PrefabStageUtility.cs):
    /// opens a prefab of the package in Prefab Mode (in isolation) and tells which prefab stage is current. Opening
    /// closes the stage that was open; the stand-in never saves a stage back to its asset.
    /// </summary>
    public static class PrefabStageUtility
    {
        static PrefabStage s_Current;

        static PrefabStageUtility() => World.WorldReset += () => s_Current = null;

        /// <summary>Get the current Prefab stage, or null when the main stage is current.</summary>
        public static PrefabStage GetCurrentPrefabStage() => s_Current;

        /// <summary>
        /// Opens a Prefab Asset in Prefab Mode (in isolation): its contents are loaded as editable scene objects whose
        /// root is <see cref="PrefabStage.prefabContentsRoot"/>, and the stage becomes current. Returns the stage.
        /// </summary>
        public static PrefabStage OpenPrefab(string prefabAssetPath)
        {
            if (string.IsNullOrEmpty(prefabAssetPath)) throw new ArgumentNullException(nameof(prefabAssetPath));
            var asset = AssetDatabase.LoadAssetAtPath<GameObject>(prefabAssetPath);
            if (asset == null) throw new ArgumentException("Prefab not found at path '" + prefabAssetPath + "'", nameof(prefabAssetPath));
            CloseCurrent();
            var root = (GameObject)Object.Clone(asset, null, worldSpace: false, hasPose: false, default, default, asset.name);
            s_Current = new PrefabStage(root, prefabAssetPath);
            return s_Current;
        }

        /// <summary>Not Unity: closes the current prefab stage (its contents are destroyed), leaving the main stage current.</summary>
        internal static void CloseCurrent()
        {
            s_Current?.Close();
            s_Current = null;
        }
    }
}
