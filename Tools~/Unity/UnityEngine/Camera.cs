namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Camera.</summary>
    public sealed class Camera : Behaviour
    {
        /// <summary>The first enabled Camera component that is tagged "MainCamera" (Read Only).</summary>
        public static Camera main => throw Shim.NotRun;
    }
}
