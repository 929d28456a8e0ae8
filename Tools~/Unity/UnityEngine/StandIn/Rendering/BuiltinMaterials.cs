using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the Built-in render pipeline's "Default-Material" (a Standard-shader material with the
    /// shader's defaults), shared, as GameObject.CreatePrimitive assigns it. World.Reset drops the cache.
    /// </summary>
    internal static class BuiltinMaterials
    {
        static Material s_Default;

        static BuiltinMaterials() => World.WorldReset += () => s_Default = null;

        /// <summary>The shared Default-Material.</summary>
        internal static Material Default
        {
            get
            {
                if (s_Default == null) s_Default = new Material(Shader.Find("Standard")) { name = "Default-Material" };
                return s_Default;
            }
        }
    }
}
