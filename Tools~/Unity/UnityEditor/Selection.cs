namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.Selection: access to the selection in the editor.</summary>
    public sealed class Selection
    {
        /// <summary>Returns the actual object selection. Includes Prefabs, non-modifiable objects.</summary>
        public static UnityEngine.Object activeObject { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
