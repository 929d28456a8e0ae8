using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: GameObjectUtility.EnsureUniqueNameForSibling as the create commands use it, with the Editor's
    /// default naming scheme "Name (1)" (Project Settings &gt; Editor &gt; Game Object Naming). Siblings are the
    /// parent's children, or the scene's root objects for a root (**approx.**: the stand-in has one scene).
    /// </summary>
    internal static class SiblingNames
    {
        /// <summary>Renames <paramref name="go"/> to "Name (n)" with the smallest free n ≥ 1 when a sibling has its name.</summary>
        internal static void MakeUnique(GameObject go)
        {
            var taken = new HashSet<string>();
            var parent = go.transform.parent;
            if (parent != null)
            {
                foreach (Transform child in parent)
                    if (child != go.transform) taken.Add(child.gameObject.name);
            }
            else
            {
                foreach (var other in World.Objects)
                    if (other != go && other != null && other.transform.parent == null) taken.Add(other.name);
            }
            if (!taken.Contains(go.name)) return;
            string stem = go.name;
            int n = 1;
            while (taken.Contains(stem + " (" + n + ")")) n++;
            go.name = stem + " (" + n + ")";
        }
    }
}
