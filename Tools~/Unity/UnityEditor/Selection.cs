using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.Selection: the editor's active object. activeGameObject is the active object when it
    /// is a GameObject (or a component's GameObject); activeTransform its Transform, never one of a prefab asset (as
    /// documented). A destroyed selection reads as null. The selection is cleared when the scene is reset.
    /// </summary>
    public sealed class Selection
    {
        static Object s_Active;

        static Selection() => World.WorldReset += () => s_Active = null;

        /// <summary>Returns the actual object selection. Includes Prefabs, non-modifiable objects.</summary>
        public static Object activeObject
        {
            get => s_Active != null ? s_Active : null;
            set => s_Active = value;
        }

        /// <summary>Returns the active game object. (The one shown in the inspector.)</summary>
        public static GameObject activeGameObject
        {
            get => activeObject as GameObject ?? (activeObject as Component)?.gameObject;
            set => s_Active = value;
        }

        /// <summary>Returns the active transform (never a prefab asset's).</summary>
        public static Transform activeTransform
        {
            get
            {
                var go = activeGameObject;
                return go != null && !SceneHooks.IsAsset(go) ? go.transform : null;
            }
            set => s_Active = value != null ? value.gameObject : null;
        }
    }
}
