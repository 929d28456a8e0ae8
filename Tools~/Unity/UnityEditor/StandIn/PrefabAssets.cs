using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the loaded prefab assets, one per file, as AssetDatabase keeps them: loading the same path
    /// again returns the same objects until the file changes or the asset is destroyed. Assets outlive scene resets,
    /// as in Unity.
    /// </summary>
    internal static class PrefabAssets
    {
        static readonly Dictionary<string, (DateTime Stamp, PrefabAsset Asset)> s_Loaded = new Dictionary<string, (DateTime, PrefabAsset)>();

        /// <summary>The prefab asset of <paramref name="file"/>, loading it when needed.</summary>
        internal static PrefabAsset Get(string file)
        {
            string full = Path.GetFullPath(file);
            var stamp = File.GetLastWriteTimeUtc(full);
            if (s_Loaded.TryGetValue(full, out var loaded) && loaded.Stamp == stamp && loaded.Asset.Root.IsAlive) return loaded.Asset;
            var asset = PrefabLoader.Load(full);
            s_Loaded[full] = (stamp, asset);
            return asset;
        }

        /// <summary>The loaded asset <paramref name="go"/> belongs to, or null.</summary>
        internal static PrefabAsset Of(UnityEngine.GameObject go)
        {
            foreach (var loaded in s_Loaded.Values)
                if (loaded.Asset.Objects.Contains(go)) return loaded.Asset;
            return null;
        }
    }
}
