using System;
using System.IO;
using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.AssetDatabase: loads the package's prefabs from their YAML ("Packages/&lt;package
    /// name&gt;/…prefab"); other asset types are outside the stand-in.
    /// </summary>
    public class AssetDatabase
    {
        /// <summary>Returns the first asset object of type type at given path assetPath (null when there is none).</summary>
        public static Object LoadAssetAtPath(string assetPath, Type type)
        {
            if (type == null) throw new ArgumentNullException(nameof(type));
            if (string.IsNullOrEmpty(assetPath)) return null;
            string file = AssetPaths.ToFile(assetPath, "AssetDatabase.LoadAssetAtPath");
            if (!File.Exists(file)) return null;
            if (!string.Equals(Path.GetExtension(file), ".prefab", StringComparison.OrdinalIgnoreCase))
                throw StandInError.Unsupported("AssetDatabase.LoadAssetAtPath of a '" + Path.GetExtension(file) + "' asset (the stand-in loads prefabs only)");
            var asset = PrefabAssets.Get(file);
            if (type.IsAssignableFrom(typeof(GameObject))) return asset.Root;
            foreach (var o in asset.Objects)
                if (type.IsInstanceOfType(o)) return o;
            return null;
        }

        /// <summary>Returns the first asset object of type T at given path assetPath (null when there is none).</summary>
        public static T LoadAssetAtPath<T>(string assetPath) where T : Object => (T)LoadAssetAtPath(assetPath, typeof(T));
    }
}
