using UnityEditor;

namespace HookeRope.Editor
{
    /// <summary>
    /// Stops the shared multi-rope world's threads before the Editor reloads the script assemblies (scripts changed, or
    /// Play entered with domain reload on): threads that outlive their domain keep waiting on events the new domain
    /// never sets. OnDisable, which Unity also sends before a reload, withdraws each rope and disposes the world when the
    /// last one goes; this is the guard for a reload that does not reach every OnDisable. See <see cref="ElasticRopeWorld"/>.
    /// </summary>
    [InitializeOnLoad]
    internal static class RopeWorldReload
    {
        static RopeWorldReload()
        {
            AssemblyReloadEvents.beforeAssemblyReload += RopeWorldScheduler.Shutdown;
        }
    }
}
