namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Gizmos: used for visual debugging or setup aids in the Scene view.</summary>
    public sealed class Gizmos
    {
        /// <summary>Sets the Color of the gizmos that are drawn next.</summary>
        public static Color color { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Draws a line starting at from towards to.</summary>
        public static void DrawLine(Vector3 from, Vector3 to) => throw Shim.NotRun;

        /// <summary>Draws a wireframe sphere with center and radius.</summary>
        public static void DrawWireSphere(Vector3 center, float radius) => throw Shim.NotRun;

        /// <summary>Draws a solid sphere with center and radius.</summary>
        public static void DrawSphere(Vector3 center, float radius) => throw Shim.NotRun;
    }
}
