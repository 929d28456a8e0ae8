using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Rigidbody: a body the physics step moves (PhysX 4 integration, see
    /// <see cref="PhysicsWorld"/> and Tools~/Unity/STAND-IN.md (Physics)). Forces from AddForce/AddTorque are accumulated
    /// and applied at the next step, as PhysX does; the body's pose is its own (the Transform is read at the start of
    /// a step when it was changed, and written after the step); mass properties come from the attached colliders.
    /// </summary>
    [DisallowMultipleComponent]
    public class Rigidbody : Component
    {
        /// <summary>Physics.defaultMaxAngularSpeed in Unity 2022.3 (rad/s): the default Rigidbody.maxAngularVelocity.</summary>
        internal const float DefaultMaxAngularSpeed = 50f;

        const float MinMass = 1e-7f, MaxMass = 1e9f;

        float m_Mass = 1f, m_Drag, m_AngularDrag = 0.05f;
        bool m_UseGravity = true, m_IsKinematic;
        RigidbodyConstraints m_Constraints;
        RigidbodyInterpolation m_Interpolation;
        Vector3 m_Velocity, m_AngularVelocity;

        // pose of the body (the Transform's position/rotation as the physics engine has it)
        Vector3 m_Position;
        Quaternion m_Rotation = Quaternion.identity;

        // accumulated until the next step: per second (Force, Acceleration) and per step (Impulse, VelocityChange)
        Vector3 m_LinearAcceleration, m_AngularAcceleration, m_LinearDeltaV, m_AngularDeltaV;

        /// <summary>The pose before the last step (Interpolate starts from it).</summary>
        internal Vector3 PreviousPosition;
        internal Quaternion PreviousRotation = Quaternion.identity;

        /// <summary>The Transform pose the physics engine last read or wrote: a different Transform pose was changed by a script.</summary>
        internal Vector3 SyncedPosition;
        internal Quaternion SyncedRotation = Quaternion.identity;

        /// <summary>The mass of the rigidbody.</summary>
        public float mass
        {
            get { EnsureAlive(); return m_Mass; }
            set
            {
                EnsureAlive();
                if (float.IsNaN(value) || float.IsInfinity(value)) { InvalidInput("mass", value.ToString(System.Globalization.CultureInfo.InvariantCulture)); return; }
                if (value < MinMass || value > MaxMass)
                    throw StandInError.Unsupported("Rigidbody.mass = " + value.ToString("R", System.Globalization.CultureInfo.InvariantCulture) +
                                                   " (outside [1e-7, 1e9] kg Unity clamps the mass; the clamp is not documented)");
                m_Mass = value;
            }
        }

        /// <summary>The drag of the object.</summary>
        public float drag
        {
            get { EnsureAlive(); return m_Drag; }
            set { EnsureAlive(); m_Drag = CheckDamping("drag", value); }
        }

        /// <summary>The angular drag of the object.</summary>
        public float angularDrag
        {
            get { EnsureAlive(); return m_AngularDrag; }
            set { EnsureAlive(); m_AngularDrag = CheckDamping("angularDrag", value); }
        }

        /// <summary>Controls whether gravity affects this rigidbody.</summary>
        public bool useGravity
        {
            get { EnsureAlive(); return m_UseGravity; }
            set { EnsureAlive(); m_UseGravity = value; }
        }

        /// <summary>Controls whether physics affects the rigidbody.</summary>
        public bool isKinematic
        {
            get { EnsureAlive(); return m_IsKinematic; }
            set
            {
                EnsureAlive();
                if (value && !m_IsKinematic)
                {
                    m_Velocity = m_AngularVelocity = Vector3.zero;
                    ClearForces();
                }
                m_IsKinematic = value;
            }
        }

        /// <summary>Interpolation provides a way to manage the appearance of jitter in the movement of your Rigidbody GameObjects at run time.</summary>
        public RigidbodyInterpolation interpolation
        {
            get { EnsureAlive(); return m_Interpolation; }
            set
            {
                EnsureAlive();
                if (value != RigidbodyInterpolation.None && value != RigidbodyInterpolation.Interpolate && value != RigidbodyInterpolation.Extrapolate)
                    throw StandInError.Unsupported("Rigidbody.interpolation = " + (int)value);
                m_Interpolation = value;
            }
        }

        /// <summary>
        /// Controls which degrees of freedom are allowed for the simulation of this Rigidbody. The stand-in supports
        /// None and FreezeRotation (no rotation at all: a character capsule); other combinations are unsupported.
        /// </summary>
        public RigidbodyConstraints constraints
        {
            get { EnsureAlive(); return m_Constraints; }
            set
            {
                EnsureAlive();
                if (value != RigidbodyConstraints.None && value != RigidbodyConstraints.FreezeRotation)
                    throw StandInError.Unsupported("Rigidbody.constraints = " + value + " (the stand-in models None and FreezeRotation)");
                m_Constraints = value;
                if (value == RigidbodyConstraints.FreezeRotation) m_AngularVelocity = Vector3.zero;
            }
        }

        /// <summary>The velocity vector of the rigidbody. It represents the rate of change of Rigidbody position.</summary>
        public Vector3 velocity
        {
            get { EnsureAlive(); return m_Velocity; }
            set
            {
                EnsureAlive();
                if (!IsFinite(value)) { InvalidInput("velocity", value); return; }
                if (m_IsKinematic) throw StandInError.Unsupported("Rigidbody.velocity set on a kinematic body");
                m_Velocity = value;
            }
        }

        /// <summary>The angular velocity vector of the rigidbody measured in radians per second.</summary>
        public Vector3 angularVelocity
        {
            get { EnsureAlive(); return m_AngularVelocity; }
            set
            {
                EnsureAlive();
                if (!IsFinite(value)) { InvalidInput("angularVelocity", value); return; }
                if (m_IsKinematic) throw StandInError.Unsupported("Rigidbody.angularVelocity set on a kinematic body");
                m_AngularVelocity = value;
            }
        }

        /// <summary>The position of the rigidbody (setting it teleports the body; the Transform follows after the next physics step).</summary>
        public Vector3 position
        {
            get { EnsureAlive(); return m_Position; }
            set
            {
                EnsureAlive();
                if (!IsFinite(value)) { InvalidInput("position", value); return; }
                m_Position = value;
                PreviousPosition = value;
            }
        }

        /// <summary>The rotation of the Rigidbody (setting it teleports the body; the Transform follows after the next physics step).</summary>
        public Quaternion rotation
        {
            get { EnsureAlive(); return m_Rotation; }
            set
            {
                EnsureAlive();
                if (!(IsFinite(value.x) && IsFinite(value.y) && IsFinite(value.z) && IsFinite(value.w)))
                {
                    InvalidInput("rotation", value.ToString());
                    return;
                }
                m_Rotation = Quaternion.Normalize(value);
                PreviousRotation = m_Rotation;
            }
        }

        /// <summary>The center of mass relative to the transform's origin (computed from the attached colliders).</summary>
        public Vector3 centerOfMass
        {
            get { EnsureAlive(); return MassProperties.Of(this).CenterOfMass; }
            set => throw StandInError.Unsupported("Rigidbody.centerOfMass (set)");
        }

        /// <summary>The center of mass of the rigidbody in world space (Read Only).</summary>
        public Vector3 worldCenterOfMass
        {
            get { EnsureAlive(); return m_Position + m_Rotation * MassProperties.Of(this).CenterOfMass; }
        }

        /// <summary>Adds a force to the Rigidbody.</summary>
        public void AddForce(Vector3 force, ForceMode mode = ForceMode.Force)
        {
            EnsureAlive();
            if (!IsFinite(force)) { InvalidInput("AddForce", force, "force"); return; }
            if (!AcceptsForces) return;
            switch (mode)
            {
                case ForceMode.Force: m_LinearAcceleration += force / m_Mass; break;
                case ForceMode.Acceleration: m_LinearAcceleration += force; break;
                case ForceMode.Impulse: m_LinearDeltaV += force / m_Mass; break;
                case ForceMode.VelocityChange: m_LinearDeltaV += force; break;
                default: throw StandInError.Unsupported("Rigidbody.AddForce with ForceMode " + (int)mode);
            }
        }

        /// <summary>Adds a torque to the rigidbody.</summary>
        public void AddTorque(Vector3 torque, ForceMode mode = ForceMode.Force)
        {
            EnsureAlive();
            if (!IsFinite(torque)) { InvalidInput("AddTorque", torque, "torque"); return; }
            if (!AcceptsForces) return;
            switch (mode)
            {
                case ForceMode.Force: m_AngularAcceleration += InverseWorldInertia(torque); break;
                case ForceMode.Acceleration: m_AngularAcceleration += torque; break;
                case ForceMode.Impulse: m_AngularDeltaV += InverseWorldInertia(torque); break;
                case ForceMode.VelocityChange: m_AngularDeltaV += torque; break;
                default: throw StandInError.Unsupported("Rigidbody.AddTorque with ForceMode " + (int)mode);
            }
        }

        /// <summary>Applies force at position. As a result this will apply a torque and force on the object.</summary>
        public void AddForceAtPosition(Vector3 force, Vector3 position, ForceMode mode = ForceMode.Force)
        {
            EnsureAlive();
            if (!IsFinite(force) || !IsFinite(position)) { InvalidInput("AddForceAtPosition", IsFinite(force) ? position : force, IsFinite(force) ? "position" : "force"); return; }
            if (!AcceptsForces) return;
            var torque = Vector3.Cross(position - worldCenterOfMass, force);
            AddForce(force, mode);
            AddTorque(torque, mode);
        }

        /// <summary>The velocity of the rigidbody at the point worldPoint in global space.</summary>
        public Vector3 GetPointVelocity(Vector3 worldPoint)
        {
            EnsureAlive();
            return m_Velocity + Vector3.Cross(m_AngularVelocity, worldPoint - worldCenterOfMass);
        }

        // ---- stand-in internals -----------------------------------------------------------------------------

        internal override void OnStandInAttached()
        {
            base.OnStandInAttached();
            var t = transform;
            m_Position = PreviousPosition = SyncedPosition = t.position;
            m_Rotation = PreviousRotation = SyncedRotation = t.rotation;
            PhysicsWorld.Add(this);
        }

        internal override void OnStandInDestroy()
        {
            PhysicsWorld.Remove(this);
            base.OnStandInDestroy();
        }

        /// <summary>In the simulation: alive and on an active GameObject (Unity removes bodies of inactive objects from the scene).</summary>
        internal bool InScene => IsAlive && Owner.IsActiveInHierarchy;

        internal bool IsDynamic => !m_IsKinematic;

        internal Vector3 PhysicsPosition => m_Position;

        internal Quaternion PhysicsRotation => m_Rotation;

        /// <summary>Moves the body to the Transform's pose (the Transform was changed by a script since physics last saw it).</summary>
        internal void TeleportToTransform(Vector3 position, Quaternion rotation)
        {
            m_Position = PreviousPosition = SyncedPosition = position;
            m_Rotation = PreviousRotation = SyncedRotation = rotation;
        }

        /// <summary>One physics step of <paramref name="dt"/> seconds: accumulated forces, gravity, damping, then the pose.</summary>
        internal void Integrate(float dt, Vector3 gravity)
        {
            PreviousPosition = m_Position;
            PreviousRotation = m_Rotation;
            if (m_IsKinematic)
            {
                ClearForces();
                return;
            }
            var com = MassProperties.Of(this).CenterOfMass;
            m_Velocity += m_LinearDeltaV + m_LinearAcceleration * dt;
            m_AngularVelocity += m_AngularDeltaV + m_AngularAcceleration * dt;
            ClearForces();
            RigidMotion.UpdateVelocity(ref m_Velocity, ref m_AngularVelocity, gravity, m_UseGravity, m_Drag, m_AngularDrag, DefaultMaxAngularSpeed, dt);
            if (m_Constraints == RigidbodyConstraints.FreezeRotation) m_AngularVelocity = Vector3.zero;
            var worldCom = m_Position + m_Rotation * com + m_Velocity * dt;
            m_Rotation = RigidMotion.Integrate(m_Rotation, m_AngularVelocity, dt);
            m_Position = worldCom - m_Rotation * com;
        }

        void ClearForces() => m_LinearAcceleration = m_AngularAcceleration = m_LinearDeltaV = m_AngularDeltaV = Vector3.zero;

        /// <summary>Unity ignores forces on kinematic bodies and on bodies outside the simulation.</summary>
        bool AcceptsForces => !m_IsKinematic && Owner.IsActiveInHierarchy;

        /// <summary>I⁻¹·τ with the inertia in world space: R·I_local⁻¹·Rᵀ·τ (PhysX converts a torque when it is added).</summary>
        Vector3 InverseWorldInertia(Vector3 torque)
        {
            var inverse = MassProperties.Of(this).Inertia.Inverse();
            return m_Rotation * inverse.Multiply(Quaternion.Inverse(m_Rotation) * torque);
        }

        static float CheckDamping(string member, float value)
        {
            if (!(value >= 0f) || float.IsInfinity(value))
                throw StandInError.Unsupported("Rigidbody." + member + " = " + value.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + " (negative or not finite)");
            return value;
        }

        static bool IsFinite(float v) => !float.IsNaN(v) && !float.IsInfinity(v);

        static bool IsFinite(Vector3 v) => IsFinite(v.x) && IsFinite(v.y) && IsFinite(v.z);

        /// <summary>Unity's error for a non-finite value: logged, the value is not assigned.</summary>
        void InvalidInput(string member, Vector3 value, string input = null) =>
            InvalidInput(member, "{ " + F(value.x) + ", " + F(value.y) + ", " + F(value.z) + " }", input);

        void InvalidInput(string member, string value, string input = null) =>
            Debug.LogError("rigidbody." + member + " assign attempt for '" + NameCore + "' is not valid. Input " + (input ?? member) + " is " + value + ".", this);

        static string F(float v) => v.ToString(System.Globalization.CultureInfo.InvariantCulture);
    }
}
