using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.Camera: no rendering; a Behaviour that Camera.main finds by its tag.</summary>
    public sealed class Camera : Behaviour
    {
        /// <summary>
        /// The first enabled Camera component that is tagged "MainCamera" (Read Only); null when there is none. "First"
        /// is the scene's creation order here (Unity returns the first valid entry of its own cache of tagged objects,
        /// an order its documentation does not give). Allocation-free, as in Unity.
        /// </summary>
        public static Camera main
        {
            get
            {
                var objects = World.Objects;
                for (int i = 0; i < objects.Count; i++)
                {
                    var go = objects[i];
                    if (!go.CompareTag("MainCamera")) continue;
                    var components = go.ComponentList;
                    for (int c = 0; c < components.Count; c++)
                        if (components[c] is Camera camera && camera.isActiveAndEnabled) return camera;
                }
                return null;
            }
        }
    }
}
