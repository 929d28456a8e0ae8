using System;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.ExecuteInEditMode: makes all instances of a script execute in Edit Mode.</summary>
    [AttributeUsage(AttributeTargets.Class, Inherited = false)]
    public sealed class ExecuteInEditMode : Attribute
    {
    }
}
