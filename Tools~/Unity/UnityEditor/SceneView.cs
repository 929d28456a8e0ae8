using HookeRope.StandIn;
using UnityEngine;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.SceneView (UCR Editor/Mono/SceneView/SceneView.cs): only the pivot of the last active
    /// Scene view, which the Editor's create commands place new objects at. The stand-in plays the Editor's default
    /// layout: one Scene view is open, with the default pivot (0, 0, 0), after every scene reset (**approx.**: there are
    /// no windows to open or close; Unity in batch mode may have none, then <see cref="lastActiveSceneView"/> is null).
    /// </summary>
    public class SceneView
    {
        static SceneView s_LastActive = new SceneView();

        static SceneView() => World.WorldReset += () => s_LastActive = new SceneView();

        SceneView() { }

        /// <summary>The SceneView that was most recently in focus (null when no Scene view is open).</summary>
        public static SceneView lastActiveSceneView => s_LastActive;

        /// <summary>The center point, or pivot, of the SceneView (world space, m); (0, 0, 0) in a new view.</summary>
        public Vector3 pivot { get; set; } = Vector3.zero;

        /// <summary>
        /// Not public in Unity (SceneView.PlaceGameObjectInFrontOfSceneView, internal): moves <paramref name="go"/> to the
        /// pivot of the last active Scene view (Unity's MoveToView(Transform): position = pivot), nothing without one.
        /// </summary>
        internal static void PlaceInFrontOfLastActive(GameObject go)
        {
            var view = lastActiveSceneView;
            if (view != null) go.transform.position = view.pivot;
        }
    }
}
