using HookeRope.StandIn;

namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.EditorApplication: the editor's play state (that of the test platform) and menu execution.</summary>
    public sealed class EditorApplication
    {
        /// <summary>Is the editor currently in play mode? (Entering or leaving Play mode from a script is outside the stand-in.)</summary>
        public static bool isPlaying
        {
            get => UnityEngine.Application.isPlaying;
            set => throw StandInError.Unsupported("EditorApplication.isPlaying (set): the test platform (Edit or Play Mode) fixes it");
        }

        /// <summary>Invokes the menu item in the specified path; false (with an error log when it does not exist) when it could not run.</summary>
        public static bool ExecuteMenuItem(string menuItemPath) => MenuItems.Execute(menuItemPath);
    }
}
