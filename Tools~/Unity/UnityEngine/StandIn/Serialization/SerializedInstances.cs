using System;
using System.Reflection;
using System.Runtime.Serialization;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: creates the object a serialized [Serializable] class or struct value is read into. Unity runs
    /// the parameterless constructor when there is one (so non-serialized fields keep their initializers) and
    /// otherwise creates the object without a constructor.
    /// </summary>
    internal static class SerializedInstances
    {
        /// <summary>A new instance of <paramref name="type"/>: through its parameterless constructor (any access) when it has one.</summary>
        internal static object Create(Type type)
        {
            if (type.IsValueType) return Activator.CreateInstance(type);
            var ctor = type.GetConstructor(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic, null, Type.EmptyTypes, null);
            if (ctor == null) return FormatterServices.GetUninitializedObject(type);
            try
            {
                return ctor.Invoke(null);
            }
            catch (TargetInvocationException e) when (e.InnerException != null)
            {
                throw e.InnerException;
            }
        }
    }
}
