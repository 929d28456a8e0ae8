using System;
using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.PrefabUtility: instantiates a prefab asset loaded by <see cref="AssetDatabase"/> into
    /// the scene, like Object.Instantiate but named as the prefab (no "(Clone)"). The instance keeps the prefab
    /// root's local position, rotation and scale. (The stand-in keeps no prefab connection.)
    /// </summary>
    public sealed class PrefabUtility
    {
        /// <summary>Instantiates the given Prefab in the scene; returns the GameObject at the root of the instance.</summary>
        public static Object InstantiatePrefab(Object assetComponentOrGameObject) => InstantiatePrefab(assetComponentOrGameObject, null);

        /// <summary>Instantiates the given Prefab under parent; returns the GameObject at the root of the instance.</summary>
        public static Object InstantiatePrefab(Object assetComponentOrGameObject, Transform parent)
        {
            if (assetComponentOrGameObject is null) throw new ArgumentNullException(nameof(assetComponentOrGameObject));
            var go = assetComponentOrGameObject as GameObject ?? (assetComponentOrGameObject as Component)?.gameObject;
            if (go == null || !SceneHooks.IsAsset(go))
                throw StandInError.Unsupported("PrefabUtility.InstantiatePrefab of '" + assetComponentOrGameObject.name +
                                               "', which is not a prefab asset loaded with AssetDatabase.LoadAssetAtPath");
            var root = go.transform.root.gameObject;
            return Object.Clone(root, parent, worldSpace: false, hasPose: false, default, default, root.name);
        }
    }
}
