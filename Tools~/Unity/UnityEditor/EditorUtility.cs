using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.EditorUtility: only InstanceIDToObject.</summary>
    public sealed partial class EditorUtility
    {
        /// <summary>
        /// The live object with that instance id, or null. The stand-in searches the scene's GameObjects and their
        /// components (not assets).
        /// </summary>
        public static Object InstanceIDToObject(int instanceID)
        {
            var objects = World.Objects;
            for (int i = 0; i < objects.Count; i++)
            {
                var go = objects[i];
                if (!go.IsAlive) continue;
                if (go.GetInstanceID() == instanceID) return go;
                var components = go.ComponentList;
                for (int c = 0; c < components.Count; c++)
                    if (components[c].IsAlive && components[c].GetInstanceID() == instanceID) return components[c];
            }
            return null;
        }
    }
}
