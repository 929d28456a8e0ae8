using System;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.AssemblyReloadEvents: events around the Editor's reload of all script assemblies (scripts
    /// changed, or entering Play mode with domain reload on). The stand-in never reloads its assemblies: a test raises
    /// the event through <see cref="InvokeBeforeAssemblyReload"/>.
    /// </summary>
    public static class AssemblyReloadEvents
    {
        /// <summary>The handler type of the reload events.</summary>
        public delegate void AssemblyReloadCallback();

        static AssemblyReloadCallback s_Before;

        /// <summary>This event is dispatched just before Unity reloads all assemblies.</summary>
        public static event AssemblyReloadCallback beforeAssemblyReload
        {
            add => s_Before += value;
            remove => s_Before -= value;
        }

        /// <summary>
        /// Not Unity: what the Editor does just before a reload (UCR OnBeforeAssemblyReload): every subscriber in order;
        /// one that throws is logged and the next one runs (approx.: UCR iterates a performance-tracked event list).
        /// </summary>
        internal static void InvokeBeforeAssemblyReload()
        {
            if (s_Before == null) return;
            foreach (var handler in s_Before.GetInvocationList())
            {
                try
                {
                    ((AssemblyReloadCallback)handler)();
                }
                catch (Exception e)
                {
                    UnityEngine.Debug.LogException(e);
                }
            }
        }
    }
}
