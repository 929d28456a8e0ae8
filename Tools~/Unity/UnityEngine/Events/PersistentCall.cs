using System;
using System.Reflection;

namespace UnityEngine.Events
{
    /// <summary>
    /// Stand-in of Unity's internal PersistentCall: one listener bound in the Inspector (target object, method name,
    /// argument mode, cached argument, call state), serialized with Unity's field names. Invoked like Unity's
    /// PersistentCall.GetRuntimeCall: skipped when Off, or RuntimeOnly outside Play; the method is looked up by name
    /// and argument types on the target's type and its base classes (instance or static, any access).
    /// </summary>
    [Serializable]
    internal sealed class PersistentCall
    {
        [SerializeField] Object m_Target;
        [SerializeField] string m_TargetAssemblyTypeName;
        [SerializeField] string m_MethodName;
        [SerializeField] PersistentListenerMode m_Mode = PersistentListenerMode.EventDefined;
        [SerializeField] ArgumentCache m_Arguments = new ArgumentCache();
        [SerializeField] UnityEventCallState m_CallState = UnityEventCallState.RuntimeOnly;

        internal Object Target => m_Target;
        internal string MethodName => m_MethodName;

        /// <summary>Calls the bound method with the event's <paramref name="eventArguments"/> (or the cached argument).</summary>
        internal void Invoke(Type[] eventTypes, object[] eventArguments)
        {
            if (m_CallState == UnityEventCallState.Off) return;
            if (m_CallState == UnityEventCallState.RuntimeOnly && !Application.isPlaying) return;
            if (string.IsNullOrEmpty(m_MethodName)) return;
            var targetType = !string.IsNullOrEmpty(m_TargetAssemblyTypeName) ? Type.GetType(m_TargetAssemblyTypeName, false) : null;
            if (targetType == null && m_Target != null) targetType = m_Target.GetType();
            if (targetType == null) return;
            Type[] types;
            object[] arguments;
            switch (m_Mode)
            {
                case PersistentListenerMode.EventDefined: types = eventTypes; arguments = eventArguments; break;
                case PersistentListenerMode.Void: types = Type.EmptyTypes; arguments = Array.Empty<object>(); break;
                case PersistentListenerMode.Int: types = new[] { typeof(int) }; arguments = new object[] { m_Arguments.IntArgument }; break;
                case PersistentListenerMode.Float: types = new[] { typeof(float) }; arguments = new object[] { m_Arguments.FloatArgument }; break;
                case PersistentListenerMode.String: types = new[] { typeof(string) }; arguments = new object[] { m_Arguments.StringArgument }; break;
                case PersistentListenerMode.Bool: types = new[] { typeof(bool) }; arguments = new object[] { m_Arguments.BoolArgument }; break;
                default:
                    var argumentType = !string.IsNullOrEmpty(m_Arguments.ObjectArgumentTypeName) ? Type.GetType(m_Arguments.ObjectArgumentTypeName, false) : null;
                    argumentType ??= typeof(Object);
                    var argument = m_Arguments.ObjectArgument;
                    types = new[] { argumentType };
                    arguments = new object[] { argument != null && argumentType.IsInstanceOfType(argument) ? argument : null };
                    break;
            }
            var method = FindMethod(targetType, m_MethodName, types);
            if (method == null) return;
            if (!method.IsStatic && m_Target == null) return;
            try
            {
                method.Invoke(method.IsStatic ? null : m_Target, arguments);
            }
            catch (TargetInvocationException e) when (e.InnerException != null)
            {
                throw e.InnerException;
            }
        }

        static MethodInfo FindMethod(Type type, string name, Type[] argumentTypes)
        {
            const BindingFlags Any = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static;
            for (var t = type; t != null && t != typeof(object); t = t.BaseType)
            {
                var method = t.GetMethod(name, Any, null, argumentTypes, null);
                if (method == null) continue;
                var parameters = method.GetParameters();
                bool valid = true;
                for (int i = 0; i < parameters.Length && valid; i++) valid = parameters[i].ParameterType.IsPrimitive == argumentTypes[i].IsPrimitive;
                if (valid) return method;
            }
            return null;
        }
    }
}
