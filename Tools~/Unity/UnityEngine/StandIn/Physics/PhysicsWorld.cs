using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the stand-in's physics scene — the registered Rigidbodies and Colliders, the global settings
    /// behind <see cref="Physics"/>, and the step: push Transforms that scripts changed into the engine, integrate
    /// every dynamic body (PhysX order: accumulated forces, gravity, damping, pose), write poses back to Transforms,
    /// then check that no dynamic body touches another collider (contacts are not solved: that throws). The player
    /// loop calls <see cref="Step"/> after FixedUpdate and <see cref="BeforeUpdate"/> before Update. Allocation-free
    /// after warm-up.
    /// </summary>
    internal static class PhysicsWorld
    {
        /// <summary>Physics.gravity's default (Project Settings &gt; Physics).</summary>
        internal static readonly Vector3 DefaultGravity = new Vector3(0f, -9.81f, 0f);

        static readonly List<Rigidbody> s_Bodies = new List<Rigidbody>();
        static readonly List<Collider> s_Colliders = new List<Collider>();

        static int s_InterpolationResetFrame = -1;

        static PhysicsWorld() => World.WorldReset += ResetState;

        internal static Vector3 Gravity = DefaultGravity;
        internal static SimulationMode Mode = SimulationMode.FixedUpdate;
        internal static bool QueriesHitTriggers = true;

        internal static IReadOnlyList<Collider> Colliders => s_Colliders;

        internal static void Add(Rigidbody body) => s_Bodies.Add(body);

        internal static void Remove(Rigidbody body) => s_Bodies.Remove(body);

        internal static void Add(Collider collider) => s_Colliders.Add(collider);

        internal static void Remove(Collider collider) => s_Colliders.Remove(collider);

        /// <summary>One simulation step of <paramref name="dt"/> seconds (Physics.Simulate, or the player loop after FixedUpdate).</summary>
        internal static void Step(float dt)
        {
            if (!(dt > 0f) || float.IsInfinity(dt))
                throw StandInError.Unsupported("a physics step of " + dt.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + " s");
            if (Mode == SimulationMode.FixedUpdate && Time.frameCount != s_InterpolationResetFrame)
            {
                s_InterpolationResetFrame = Time.frameCount;
                ResetInterpolationPoses();
            }
            SyncTransforms();
            var gravity = Gravity;
            for (int i = 0; i < s_Bodies.Count; i++)
            {
                var body = s_Bodies[i];
                if (body.InScene) body.Integrate(dt, gravity);
            }
            // parents before children: writing a parent's Transform moves its children's
            bool interpolating = Mode == SimulationMode.FixedUpdate;
            for (int depth = 0, deepest = 0; depth <= deepest; depth++)
            {
                for (int i = 0; i < s_Bodies.Count; i++)
                {
                    var body = s_Bodies[i];
                    if (!body.InScene) continue;
                    int d = Depth(body.transform);
                    if (d > deepest) deepest = d;
                    if (d != depth) continue;
                    // Interpolate/Extrapolate bodies get their Transform from BeforeUpdate when the player loop runs physics
                    if (interpolating && Interpolates(body)) continue;
                    WriteTransform(body, body.PhysicsPosition, body.PhysicsRotation);
                }
            }
            ContactCheck.AfterStep(s_Colliders);
        }

        /// <summary>
        /// Before Update (PhysicsScene.InterpolateBodies, automatic for the default scene): Transforms of interpolating
        /// bodies between the last two physics poses, alpha = (Time.time − Time.fixedTime) / Time.fixedDeltaTime;
        /// extrapolating ones ahead of the last pose by their velocities.
        /// </summary>
        internal static void BeforeUpdate()
        {
            if (Mode != SimulationMode.FixedUpdate) return;
            float ahead = Time.time - Time.fixedTime;
            float alpha = Clamp01(ahead / Time.fixedDeltaTime);
            for (int i = 0; i < s_Bodies.Count; i++)
            {
                var body = s_Bodies[i];
                if (!Interpolates(body)) continue;
                if (body.interpolation == RigidbodyInterpolation.Interpolate)
                    WriteTransform(body, Vector3.LerpUnclamped(body.PreviousPosition, body.PhysicsPosition, alpha),
                        Quaternion.Slerp(body.PreviousRotation, body.PhysicsRotation, alpha));
                else
                    WriteTransform(body, body.PhysicsPosition + body.velocity * ahead,
                        RigidMotion.Integrate(body.PhysicsRotation, body.angularVelocity, ahead));
            }
        }

        /// <summary>
        /// PhysicsScene.ResetInterpolationPoses, automatic for the default scene before the first step of a frame:
        /// Transforms of interpolating and extrapolating bodies go back to the bodies' poses, so their interpolated
        /// poses (or a script's edits of them) are not synced into the engine.
        /// </summary>
        static void ResetInterpolationPoses()
        {
            for (int i = 0; i < s_Bodies.Count; i++)
            {
                var body = s_Bodies[i];
                if (Interpolates(body)) WriteTransform(body, body.PhysicsPosition, body.PhysicsRotation);
            }
        }

        static bool Interpolates(Rigidbody body) => body.InScene && body.IsDynamic && body.interpolation != RigidbodyInterpolation.None;

        /// <summary>
        /// Physics.SyncTransforms: bodies whose Transform a script changed since physics last read or wrote it move
        /// there (velocity kept); every collider takes its Transform's current pose.
        /// </summary>
        internal static void SyncTransforms()
        {
            for (int i = 0; i < s_Bodies.Count; i++)
            {
                var body = s_Bodies[i];
                if (!body.InScene) continue;
                var t = body.transform;
                Vector3 position = t.position;
                Quaternion rotation = t.rotation;
                if (!Same(position, body.SyncedPosition) || !Same(rotation, body.SyncedRotation)) body.TeleportToTransform(position, rotation);
            }
            for (int i = 0; i < s_Colliders.Count; i++)
                if (s_Colliders[i].IsAlive) s_Colliders[i].SyncTransform();
        }

        /// <summary>
        /// For a cloner that places a new hierarchy after creating its components (Object.Instantiate(original, position,
        /// rotation)): Unity creates the clone's bodies and colliders where the clone is, so they take the Transforms now.
        /// </summary>
        internal static void HierarchyPlaced(Transform root)
        {
            var components = root.gameObject.ComponentList;
            for (int i = 0; i < components.Count; i++)
            {
                if (!components[i].IsAlive) continue;
                if (components[i] is Collider collider) collider.SyncTransform();
                else if (components[i] is Rigidbody body) body.TeleportToTransform(root.position, root.rotation);
            }
            var children = root.ChildList;
            for (int i = 0; i < children.Count; i++) HierarchyPlaced(children[i]);
        }

        /// <summary>Physics.OverlapSphereNonAlloc over the registered colliders (in the order they were added).</summary>
        internal static int OverlapSphere(Vector3 position, float radius, Collider[] results, int layerMask, QueryTriggerInteraction queryTriggerInteraction)
        {
            bool hitTriggers = HitsTriggers(queryTriggerInteraction);
            int count = 0;
            for (int i = 0; i < s_Colliders.Count && count < results.Length; i++)
            {
                var collider = s_Colliders[i];
                if (!Queried(collider, layerMask, hitTriggers, "Physics.OverlapSphereNonAlloc", out var shape)) continue;
                if (ShapeOverlap.SphereTouches(position, radius, shape)) results[count++] = collider;
            }
            return count;
        }

        /// <summary>
        /// Physics.RaycastAll over the registered colliders (in the order they were added): every collider the ray
        /// (unit <paramref name="direction"/>) enters within <paramref name="maxDistance"/> m, not those it starts
        /// inside; layer and trigger rules as <see cref="OverlapSphere"/>. Allocates the result array, as Unity does.
        /// </summary>
        internal static RaycastHit[] RaycastAll(Vector3 origin, Vector3 direction, float maxDistance, int layerMask, QueryTriggerInteraction queryTriggerInteraction)
        {
            bool hitTriggers = HitsTriggers(queryTriggerInteraction);
            var hits = new List<RaycastHit>();
            for (int i = 0; i < s_Colliders.Count; i++)
            {
                var collider = s_Colliders[i];
                if (!Queried(collider, layerMask, hitTriggers, "Physics.RaycastAll", out var shape)) continue;
                // mesh rectangles are one-sided for raycasts (Physics.queriesHitBackfaces, false by default, is not modelled)
                if (collider is MeshCollider mesh && !(Vector3.Dot(direction, mesh.FrontNormal(collider.PhysicsFrame(collider.attachedRigidbody))) < 0f)) continue;
                if (!ShapeRaycast.Enter(origin, direction, shape, out double distance, out Vector3 normal) || !(distance <= maxDistance)) continue;
                hits.Add(new RaycastHit(ShapeRaycast.At(origin, direction, distance), normal, (float)distance, collider));
            }
            return hits.ToArray();
        }

        /// <summary>Whether a query with <paramref name="interaction"/> reports triggers (UseGlobal: Physics.queriesHitTriggers).</summary>
        static bool HitsTriggers(QueryTriggerInteraction interaction) =>
            interaction == QueryTriggerInteraction.Collide || interaction == QueryTriggerInteraction.UseGlobal && QueriesHitTriggers;

        /// <summary>
        /// Whether a query (named <paramref name="query"/> for the exception) looks at <paramref name="collider"/>: in the
        /// scene, on a layer in <paramref name="layerMask"/>, not a trigger unless <paramref name="hitTriggers"/>; then its
        /// shape as the engine has it (throws for geometry the stand-in cannot test).
        /// </summary>
        static bool Queried(Collider collider, int layerMask, bool hitTriggers, string query, out WorldShape shape)
        {
            shape = WorldShape.Nothing;
            collider.SyncIfRejoined();
            if (!collider.InScene) return false;
            if ((layerMask & (1 << collider.gameObject.layer)) == 0) return false;
            if (collider.isTrigger && !hitTriggers) return false;
            shape = collider.PhysicsShape(collider.attachedRigidbody);
            if (shape.Kind == ShapeKind.Unsupported) throw StandInError.Unsupported(shape.Unsupported + " in " + query);
            return true;
        }

        static void WriteTransform(Rigidbody body, Vector3 position, Quaternion rotation)
        {
            var t = body.transform;
            t.position = position;
            t.rotation = rotation;
            body.SyncedPosition = t.position;
            body.SyncedRotation = t.rotation;
        }

        /// <summary>Exact equality (Vector3 == is approximate in Unity): any change a script made counts.</summary>
        static bool Same(Vector3 a, Vector3 b) => a.x.Equals(b.x) && a.y.Equals(b.y) && a.z.Equals(b.z);

        static bool Same(Quaternion a, Quaternion b) => a.x.Equals(b.x) && a.y.Equals(b.y) && a.z.Equals(b.z) && a.w.Equals(b.w);

        static int Depth(Transform t)
        {
            int depth = 0;
            for (var p = t.ParentCore; p is object; p = p.ParentCore) depth++;
            return depth;
        }

        static float Clamp01(float v) => v < 0f ? 0f : v > 1f ? 1f : v;

        static void ResetState()
        {
            s_Bodies.Clear();
            s_Colliders.Clear();
            ContactCheck.Reset();
            Gravity = DefaultGravity;
            Mode = SimulationMode.FixedUpdate;
            QueriesHitTriggers = true;
            s_InterpolationResetFrame = -1;
        }
    }
}
