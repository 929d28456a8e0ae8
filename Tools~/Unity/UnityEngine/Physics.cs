using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Physics: global physics properties and helper methods. The scene, the step and the
    /// queries live in <see cref="PhysicsWorld"/>; what the stand-in approximates is listed in Tools~/Unity/STAND-IN.md (Physics).
    /// </summary>
    public class Physics
    {
        /// <summary>Layer mask constant to select ignore raycast layer.</summary>
        public const int IgnoreRaycastLayer = 1 << 2;

        /// <summary>Layer mask constant to select default raycast layers.</summary>
        public const int DefaultRaycastLayers = ~IgnoreRaycastLayer;

        /// <summary>Layer mask constant to select all layers.</summary>
        public const int AllLayers = ~0;

        /// <summary>The gravity applied to all rigid bodies in the Scene.</summary>
        public static Vector3 gravity
        {
            get => PhysicsWorld.Gravity;
            set => PhysicsWorld.Gravity = value;
        }

        /// <summary>Specifies whether queries (raycasts, spherecasts, overlap tests, etc.) hit Triggers by default.</summary>
        public static bool queriesHitTriggers
        {
            get => PhysicsWorld.QueriesHitTriggers;
            set => PhysicsWorld.QueriesHitTriggers = value;
        }

        /// <summary>Controls when Unity executes the physics simulation.</summary>
        public static SimulationMode simulationMode
        {
            get => PhysicsWorld.Mode;
            set
            {
                if (value != SimulationMode.FixedUpdate && value != SimulationMode.Script)
                    throw StandInError.Unsupported("Physics.simulationMode = SimulationMode." + value +
                                                   " (the stand-in simulates after FixedUpdate or in Physics.Simulate only)");
                PhysicsWorld.Mode = value;
            }
        }

        /// <summary>Simulate physics in the Scene.</summary>
        public static void Simulate(float step)
        {
            if (simulationMode != SimulationMode.Script)
            {
                Debug.LogWarning("Physics.Simulate(...) was called but simulation mode is not set to Script. You should set simulation mode to Script first before calling this function therefore the simulation was not run.");
                return;
            }
            PhysicsWorld.Step(step);
        }

        /// <summary>Apply Transform changes to the physics engine.</summary>
        public static void SyncTransforms() => PhysicsWorld.SyncTransforms();

        /// <summary>Computes and stores colliders touching or inside the sphere into the provided buffer.</summary>
        public static int OverlapSphereNonAlloc(Vector3 position, float radius, Collider[] results, int layerMask = AllLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            if (results == null) throw new ArgumentNullException(nameof(results));
            return PhysicsWorld.OverlapSphere(position, radius, results, layerMask, queryTriggerInteraction);
        }

        /// <summary>Casts a ray, from point origin, in direction direction, of length maxDistance, against all colliders in the Scene; the nearest hit goes to hitInfo.</summary>
        public static bool Raycast(Vector3 origin, Vector3 direction, out RaycastHit hitInfo, float maxDistance = float.PositiveInfinity, int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            hitInfo = default;
            bool found = false;
            var hits = RaycastAll(origin, direction, maxDistance, layerMask, queryTriggerInteraction);
            for (int i = 0; i < hits.Length; i++)
            {
                if (found && !(hits[i].distance < hitInfo.distance)) continue;
                hitInfo = hits[i];
                found = true;
            }
            return found;
        }

        /// <summary>Casts a ray through the Scene and returns all hits. Note that order of the results is undefined.</summary>
        public static RaycastHit[] RaycastAll(Vector3 origin, Vector3 direction, float maxDistance = float.PositiveInfinity, int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            float length = direction.magnitude;
            if (!(length > float.Epsilon)) return new RaycastHit[0];
            return PhysicsWorld.RaycastAll(origin, direction / length, maxDistance, layerMask, queryTriggerInteraction);
        }
    }
}
