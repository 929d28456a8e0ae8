using System;
using System.Reflection;
using System.Runtime.CompilerServices;
using UnityEditor;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the editor's assembly load. Unity runs the static constructor of every [InitializeOnLoad]
    /// class when it loads (or reloads) the editor's script assemblies; the stand-in loads them once per process, so
    /// <see cref="Run"/> (called by the test run before its first test) runs those static constructors once, over the
    /// script assemblies that reference UnityEditor. A static constructor that throws is logged as an exception.
    /// </summary>
    internal static class EditorLoad
    {
        static bool s_Done;

        internal static void Run()
        {
            if (s_Done) return;
            s_Done = true;
            foreach (var type in ScriptAssemblies.Types())
            {
                if (type.GetCustomAttribute<InitializeOnLoadAttribute>(false) == null) continue;
                try
                {
                    RuntimeHelpers.RunClassConstructor(type.TypeHandle);
                }
                catch (TypeInitializationException e)
                {
                    UnityEngine.Debug.LogException(e.InnerException ?? e);
                }
            }
        }
    }
}
