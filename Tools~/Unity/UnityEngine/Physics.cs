namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Physics: global physics properties and helper methods.</summary>
    public class Physics
    {
        /// <summary>Layer mask constant to select all layers.</summary>
        public const int AllLayers = -1;

        /// <summary>Controls when Unity executes the physics simulation.</summary>
        public static SimulationMode simulationMode { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Simulate physics in the Scene.</summary>
        public static void Simulate(float step) => throw Shim.NotRun;

        /// <summary>Computes and stores colliders touching or inside the sphere into the provided buffer.</summary>
        public static int OverlapSphereNonAlloc(Vector3 position, float radius, Collider[] results, int layerMask = AllLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal) => throw Shim.NotRun;
    }
}
