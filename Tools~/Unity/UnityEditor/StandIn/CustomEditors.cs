using System;
using UnityEditor;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: finds the [CustomEditor] class for an inspected type among the loaded assemblies: an editor
    /// for exactly that type first, then one for a base class with editorForChildClasses; fallback editors only
    /// when nothing else matches. No match → the plain Editor (Unity's generic inspector).
    /// </summary>
    internal static class CustomEditors
    {
        internal static Type For(Type inspected)
        {
            Type best = null;
            int bestRank = int.MaxValue;
            foreach (var type in ScriptAssemblies.Types())
            {
                if (!typeof(Editor).IsAssignableFrom(type) || type.IsAbstract) continue;
                foreach (CustomEditor attribute in type.GetCustomAttributes(typeof(CustomEditor), false))
                {
                    int rank = Rank(attribute, inspected);
                    if (rank < bestRank) { best = type; bestRank = rank; }
                }
            }
            return best ?? typeof(Editor);
        }

        /// <summary>0 exact, 1 + base distance for child-class editors, +1000 for fallbacks; int.MaxValue no match.</summary>
        static int Rank(CustomEditor attribute, Type inspected)
        {
            var target = attribute.m_InspectedType;
            if (target == null) return int.MaxValue;
            int rank = int.MaxValue;
            if (target == inspected) rank = 0;
            else if (attribute.m_EditorForChildClasses)
            {
                int distance = 1;
                for (var t = inspected.BaseType; t != null; t = t.BaseType, distance++)
                    if (t == target) { rank = distance; break; }
            }
            if (rank != int.MaxValue && attribute.isFallback) rank += 1000;
            return rank;
        }
    }
}
