using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.Camera: no rendering; only Camera.main for scenes without cameras.</summary>
    public sealed class Camera : Behaviour
    {
        /// <summary>
        /// The first enabled Camera component that is tagged "MainCamera" (Read Only). Null when the scene has no
        /// Camera (as in Unity); with a Camera in the scene it throws, since the stand-in does not model tags.
        /// </summary>
        public static Camera main
        {
            get
            {
                using (var cameras = World.Live<Camera>().GetEnumerator())
                    if (cameras.MoveNext())
                        throw StandInError.Unsupported("Camera.main with a Camera in the scene (GameObject tags are not modelled)");
                return null;
            }
        }
    }
}
