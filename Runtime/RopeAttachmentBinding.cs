using HookeRope.Solver;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// Couples the two ends of an <see cref="ElasticRope"/> with Unity: pins the end particles to Transforms (an
    /// anchor, an XR hand), loads them with Rigidbodies (two-way) or with rigs without a Rigidbody
    /// (<see cref="KinematicRigLoad"/>). Before each rope step it applies the pending velocity correction to the
    /// bodies and copies the attachment poses in; after the step it applies the rope's force to the bodies
    /// (semi-implicit Euler, see <see cref="Rope.GetLoadHostForce"/>), records where the rigs must move and the force
    /// the rope applied on each end. Positions go into the rope's frame: world axes, origin at the origin passed in
    /// (m). Allocation-free per step.
    /// </summary>
    internal sealed class RopeAttachmentBinding
    {
        RopeEnd _start, _end;
        int _startPin = -1, _endPin = -1, _startLoad = -1, _endLoad = -1;
        Vector3 _startVelocityCorrection, _endVelocityCorrection;
        readonly KinematicRigLoad _startRig = new KinematicRigLoad(), _endRig = new KinematicRigLoad();

        /// <summary>The load id of the end Rigidbody or rig, or -1 when the end is neither.</summary>
        public int EndLoad => _endLoad;

        /// <summary>Force in N (world) the rope applied on the start attachment over the last step; zero for a free end.</summary>
        public Vector3 StartForce { get; private set; }

        /// <summary>Force in N (world) the rope applied on the end attachment over the last step; zero for a free end.</summary>
        public Vector3 EndForce { get; private set; }

        /// <summary>The rig coupling of the start (meaningful when the start is a <see cref="RopeEndKind.KinematicRig"/>).</summary>
        public KinematicRigLoad StartRig => _startRig;

        /// <summary>The rig coupling of the end (meaningful when the end is a <see cref="RopeEndKind.KinematicRig"/>).</summary>
        public KinematicRigLoad EndRig => _endRig;

        /// <summary>
        /// Pins (Transform end) or loads (Rigidbody end) the first and last particle of <paramref name="rope"/>;
        /// <paramref name="origin"/> is the world position (m) of the rope frame's origin and
        /// <paramref name="compliance"/> the compliance of the Transform pins (m/N). Clears the pending velocity corrections.
        /// </summary>
        public void Attach(Rope rope, RopeEnd start, RopeEnd end, Vector3 origin, float compliance)
        {
            _start = start;
            _end = end;
            AttachEnd(rope, start, 0, origin, compliance, out _startPin, out _startLoad);
            AttachEnd(rope, end, rope.ParticleCount - 1, origin, compliance, out _endPin, out _endLoad);
            _startVelocityCorrection = _endVelocityCorrection = Vector3.zero;
            StartForce = EndForce = Vector3.zero;
            _startRig.Reset();
            _endRig.Reset();
        }

        /// <summary>
        /// Before a rope step of <paramref name="deltaTime"/> s: adds the velocity corrections of the last step to the
        /// bodies, then copies the Transform targets, the body positions and velocities and the rig positions and
        /// velocities into <paramref name="rope"/>.
        /// </summary>
        public void CopyIn(Rope rope, Vector3 origin, float deltaTime)
        {
            CorrectBodyVelocity(_start, ref _startVelocityCorrection);
            CorrectBodyVelocity(_end, ref _endVelocityCorrection);
            CopyIn(rope, origin, deltaTime, _start, _startPin, _startLoad, _startRig);
            CopyIn(rope, origin, deltaTime, _end, _endPin, _endLoad, _endRig);
        }

        /// <summary>
        /// After a rope step: applies the rope's force to the attached bodies and keeps the velocity corrections for
        /// the next step, records where the rigs must move, and the force the rope applied on each end.
        /// </summary>
        public void ApplyForces(Rope rope)
        {
            StartForce = ApplyForceToEnd(rope, _start, _startPin, _startLoad, _startRig, ref _startVelocityCorrection);
            EndForce = ApplyForceToEnd(rope, _end, _endPin, _endLoad, _endRig, ref _endVelocityCorrection);
        }

        /// <summary>Pins (Transform end) or loads (Rigidbody end) <paramref name="particle"/>; the id not created is -1.</summary>
        static void AttachEnd(Rope rope, RopeEnd end, int particle, Vector3 origin, float compliance, out int pin, out int load)
        {
            pin = load = -1;
            switch (end.Kind)
            {
                case RopeEndKind.Transform:
                    pin = rope.AddPin(particle, end.Point.position.RelativeTo(origin), compliance);
                    break;
                case RopeEndKind.Rigidbody:
                    load = rope.AddLoad(particle, end.Body.mass);
                    break;
                case RopeEndKind.KinematicRig:
                    load = rope.AddLoad(particle, end.RigMass);
                    break;
            }
        }

        static void CopyIn(Rope rope, Vector3 origin, float deltaTime, RopeEnd end, int pin, int load, KinematicRigLoad rig)
        {
            if (pin >= 0 && end.Point != null)
            {
                rope.SetPinTarget(pin, end.Point.position.RelativeTo(origin));
            }
            else if (load >= 0 && end.Body != null)
            {
                Vector3 point = end.PhysicsPosition();
                rope.SetLoadState(load, point.RelativeTo(origin), end.Body.GetPointVelocity(point).ToFloat3());
            }
            else if (load >= 0 && end.Kind == RopeEndKind.KinematicRig)
            {
                Vector3 world = end.Point.position;
                rig.BeforeStep(rope, load, world.RelativeTo(origin), deltaTime, PositionRounding(world));
            }
        }

        /// <summary>
        /// Rounding (m) of a world position stored in float: 4 units in the last place of its largest coordinate (a
        /// Transform moved by a displacement lands within that of the sum), at least 1 µm.
        /// </summary>
        static float PositionRounding(Vector3 world)
        {
            float largest = System.Math.Max(System.Math.Abs(world.x), System.Math.Max(System.Math.Abs(world.y), System.Math.Abs(world.z)));
            return System.Math.Max(1e-6f, 4f * 1.1920929e-7f * largest);
        }

        /// <summary>
        /// After the rope step, one end: a pin reports the pin force; a Rigidbody load gets the host force (see
        /// <see cref="ApplyForceToBody"/>) and reports it; a rig load records where the rig must move and reports the
        /// rope's mean force on the rig over the step, M·(Δv/Δt − g) (<see cref="Rope.GetLoadForce"/>). Returns the
        /// force in N (world) the rope applied on the attachment; zero for a free end.
        /// </summary>
        static Vector3 ApplyForceToEnd(Rope rope, RopeEnd end, int pin, int load, KinematicRigLoad rig, ref Vector3 velocityCorrection)
        {
            if (pin >= 0) return rope.GetPinForce(pin).ToVector3();
            if (load < 0) return Vector3.zero;
            if (end.Body != null) return ApplyForceToBody(rope, end, load, ref velocityCorrection);
            if (end.Kind != RopeEndKind.KinematicRig) return Vector3.zero;
            rig.AfterStep(rope, load);
            return rope.GetLoadForce(load).ToVector3();
        }

        /// <summary>
        /// Two-way coupling, after the rope step: the force that brings the body (integrated by the physics engine
        /// with semi-implicit Euler) to where the rope's load particle ended, and the velocity correction that the
        /// next step adds before it reads the body back (see <see cref="Rope.GetLoadHostForce"/>).
        /// </summary>
        static Vector3 ApplyForceToBody(Rope rope, RopeEnd end, int load, ref Vector3 velocityCorrection)
        {
            velocityCorrection = Vector3.zero;
            Vector3 force = rope.GetLoadHostForce(load).ToVector3();
            if (end.Body.isKinematic) return force;
            end.Body.AddForceAtPosition(force, end.PhysicsPosition(), ForceMode.Force);
            velocityCorrection = rope.GetLoadHostVelocityCorrection(load).ToVector3();
            return force;
        }

        static void CorrectBodyVelocity(RopeEnd end, ref Vector3 velocityCorrection)
        {
            if (end != null && end.Body != null && !end.Body.isKinematic) end.Body.velocity += velocityCorrection;
            velocityCorrection = Vector3.zero;
        }
    }
}
