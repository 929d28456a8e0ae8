namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.MenuCommand: used to extract the context for a MenuItem.</summary>
    public sealed class MenuCommand
    {
        /// <summary>Context is the object that is the target of a menu command.</summary>
        public UnityEngine.Object context;

        /// <summary>Creates a new MenuCommand object.</summary>
        public MenuCommand(UnityEngine.Object inContext) => throw Shim.NotRun;
    }
}
