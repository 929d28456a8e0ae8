namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.MenuCommand: used to extract the context for a MenuItem.</summary>
    public sealed class MenuCommand
    {
        /// <summary>Context is the object that is the target of a menu command.</summary>
        public UnityEngine.Object context;

        /// <summary>An integer for passing custom information to a menu item.</summary>
        public int userData;

        /// <summary>Creates a new MenuCommand object.</summary>
        public MenuCommand(UnityEngine.Object inContext, int inUserData)
        {
            context = inContext;
            userData = inUserData;
        }

        /// <summary>Creates a new MenuCommand object.</summary>
        public MenuCommand(UnityEngine.Object inContext) : this(inContext, 0) { }
    }
}
