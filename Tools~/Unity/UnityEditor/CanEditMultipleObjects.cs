using System;

namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.CanEditMultipleObjects: attribute used to make a custom editor support multi-object editing.</summary>
    [AttributeUsage(AttributeTargets.Class)]
    public sealed class CanEditMultipleObjects : Attribute
    {
    }
}
