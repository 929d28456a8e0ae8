using System;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.ExecuteAlways: makes instances of a script always execute, both as part of Play Mode and when editing.</summary>
    [AttributeUsage(AttributeTargets.Class, Inherited = false)]
    public sealed class ExecuteAlways : Attribute
    {
    }
}
