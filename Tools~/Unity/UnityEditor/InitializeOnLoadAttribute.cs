using System;

namespace UnityEditor
{
    /// <summary>
    /// Marks a class as requiring eager initialization: its static constructor runs when the editor assemblies are
    /// loaded (the stand-in: once per process, at the start of a test run; see HookeRope.StandIn.EditorLoad).
    /// </summary>
    [AttributeUsage(AttributeTargets.Class)]
    public class InitializeOnLoadAttribute : Attribute
    {
    }
}
