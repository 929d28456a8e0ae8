using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: a prefab loaded from its YAML file: the root GameObject (an asset, outside the scene) and what the load found.</summary>
    internal sealed class PrefabAsset
    {
        internal PrefabAsset(string file, GameObject root, List<Object> objects, List<string> missingFields)
        {
            File = file;
            Root = root;
            Objects = objects;
            MissingFields = missingFields;
        }

        /// <summary>The prefab file.</summary>
        internal string File { get; }

        /// <summary>The prefab's root GameObject.</summary>
        internal GameObject Root { get; }

        /// <summary>Every object of the file (GameObjects and components) in file order.</summary>
        internal IReadOnlyList<Object> Objects { get; }

        /// <summary>Serialized script fields ("Class.path") the file does not mention (they keep their constructor values, as in Unity).</summary>
        internal IReadOnlyList<string> MissingFields { get; }
    }
}
