using System;
using HookeRope.StandIn;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.ObjectChangeEvents: the undoable changes recorded since the last editor update, published
    /// once per update (the stand-in: see <see cref="ObjectChangeLog"/> for what is recorded and when it is published).
    /// </summary>
    public static class ObjectChangeEvents
    {
        /// <summary>The handler of <see cref="changesPublished"/>; the stream is only valid during the call.</summary>
        public delegate void ObjectChangeEventsHandler(ref ObjectChangeEventStream stream);

        /// <summary>Raised once per editor update when undoable changes were recorded since the last one, in the order they were applied.</summary>
        public static event ObjectChangeEventsHandler changesPublished
        {
            add => s_Handlers += value;
            remove => s_Handlers -= value;
        }

        static ObjectChangeEventsHandler s_Handlers;

        /// <summary>Not Unity: calls every subscriber with <paramref name="stream"/> (an exception is logged and the next subscriber runs).</summary>
        internal static void Invoke(ref ObjectChangeEventStream stream)
        {
            if (s_Handlers == null || stream.length == 0) return;
            foreach (var handler in s_Handlers.GetInvocationList())
            {
                try
                {
                    ((ObjectChangeEventsHandler)handler)(ref stream);
                }
                catch (Exception e)
                {
                    UnityEngine.Debug.LogException(e);
                }
            }
        }
    }
}
