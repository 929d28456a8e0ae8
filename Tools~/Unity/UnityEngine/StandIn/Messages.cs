using System;
using System.Collections;
using System.Collections.Generic;
using System.Reflection;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: sends Unity messages (Awake, OnEnable, Start, FixedUpdate, Update, LateUpdate, OnDisable,
    /// OnDestroy, OnValidate, Reset) to MonoBehaviours by name, as Unity does: any access modifier, declared on the
    /// class or a base class, no parameters. An exception thrown by a message is logged with
    /// <see cref="Debug.LogException(Exception, UnityEngine.Object)"/> and the loop goes on, as in Unity (the test
    /// run then fails on the unexpected exception log).
    /// </summary>
    internal static class Messages
    {
        static readonly Dictionary<(Type, string), MethodInfo> s_Cache = new Dictionary<(Type, string), MethodInfo>();
        const BindingFlags Instance = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly;

        /// <summary>The message method <paramref name="message"/> of <paramref name="type"/>, or null.</summary>
        internal static MethodInfo Find(Type type, string message)
        {
            if (s_Cache.TryGetValue((type, message), out var cached)) return cached;
            MethodInfo found = null;
            for (var t = type; t != null && t != typeof(MonoBehaviour) && found == null; t = t.BaseType)
            {
                var method = t.GetMethod(message, Instance, null, Type.EmptyTypes, null);
                if (method != null) found = method;
            }
            if (found != null && typeof(IEnumerator).IsAssignableFrom(found.ReturnType))
                throw StandInError.Unsupported(type.Name + "." + message + " as a coroutine");
            s_Cache[(type, message)] = found;
            return found;
        }

        /// <summary>True when <paramref name="type"/> implements <paramref name="message"/>.</summary>
        internal static bool Has(Type type, string message) => Find(type, message) != null;

        /// <summary>A delegate bound to <paramref name="target"/>'s <paramref name="message"/> method, or null when it has none.</summary>
        internal static Action Bind(Component target, string message)
        {
            var method = Find(target.GetType(), message);
            return method == null ? null : (Action)Delegate.CreateDelegate(typeof(Action), target, method);
        }

        /// <summary>Invokes <paramref name="message"/> on <paramref name="target"/> when it implements it; exceptions are logged, not thrown.</summary>
        internal static void Send(Component target, string message)
        {
            var method = Find(target.GetType(), message);
            if (method == null) return;
            try
            {
                method.Invoke(target, null);
            }
            catch (TargetInvocationException e)
            {
                Debug.LogException(e.InnerException ?? e, target);
            }
        }
    }
}
