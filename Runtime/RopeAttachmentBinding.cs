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
        RopeInputGuard _guard;
        float _compliance;
        int _startPin = -1, _endPin = -1, _startLoad = -1, _endLoad = -1;
        bool _startPoseValid, _endPoseValid;
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
        /// <paramref name="compliance"/> the compliance of the Transform pins (m/N). A Rigidbody whose mass the
        /// <paramref name="guard"/> rejects is pinned instead (kinematic); a non-finite pose pins the end where the rope
        /// was laid out. Clears the pending velocity corrections.
        /// </summary>
        public void Attach(Rope rope, RopeEnd start, RopeEnd end, Vector3 origin, float compliance, RopeInputGuard guard)
        {
            _start = start;
            _end = end;
            _guard = guard;
            _compliance = compliance;
            AttachEnd(rope, RopeInputGuard.Start, start, 0, origin, out _startPin, out _startLoad);
            AttachEnd(rope, RopeInputGuard.End, end, rope.ParticleCount - 1, origin, out _endPin, out _endLoad);
            _startVelocityCorrection = _endVelocityCorrection = Vector3.zero;
            StartForce = EndForce = Vector3.zero;
            _startRig.Reset();
            _endRig.Reset();
        }

        /// <summary>
        /// Before a rope step: re-attaches an end whose Point or Body was destroyed since the build (to what is left:
        /// its Point as a Transform end, or nothing), adds the velocity corrections of the last step to the bodies,
        /// then copies the Transform targets, the body positions and velocities and the rig positions and velocities
        /// (for a step of <paramref name="deltaTime"/> s) into <paramref name="rope"/>; an end
        /// whose pose is not finite keeps its last one. Returns true when an end was re-attached (the end load may have
        /// changed). Allocation-free unless an end was re-attached.
        /// </summary>
        public bool CopyIn(Rope rope, Vector3 origin, float deltaTime)
        {
            bool reattached = false;
            if (_guard.TakeDestroyed(RopeInputGuard.Start, _start))
            {
                Reattach(rope, RopeInputGuard.Start, _start, 0, origin, ref _startPin, ref _startLoad, ref _startVelocityCorrection);
                _startRig.Reset();
                reattached = true;
            }
            if (_guard.TakeDestroyed(RopeInputGuard.End, _end))
            {
                Reattach(rope, RopeInputGuard.End, _end, rope.ParticleCount - 1, origin, ref _endPin, ref _endLoad, ref _endVelocityCorrection);
                _endRig.Reset();
                reattached = true;
            }
            CorrectBodyVelocity(_start, _startLoad, ref _startVelocityCorrection);
            CorrectBodyVelocity(_end, _endLoad, ref _endVelocityCorrection);
            _startPoseValid = CopyIn(rope, origin, deltaTime, RopeInputGuard.Start, _start, _startPin, _startLoad, _startRig);
            _endPoseValid = CopyIn(rope, origin, deltaTime, RopeInputGuard.End, _end, _endPin, _endLoad, _endRig);
            return reattached;
        }

        /// <summary>
        /// After a rope step: applies the rope's force to the attached bodies and keeps the velocity corrections for
        /// the next step, records where the rigs must move, and the force the rope applied on each end.
        /// </summary>
        public void ApplyForces(Rope rope)
        {
            StartForce = ApplyForceToEnd(rope, _start, _startPin, _startLoad, _startPoseValid, _startRig, ref _startVelocityCorrection);
            EndForce = ApplyForceToEnd(rope, _end, _endPin, _endLoad, _endPoseValid, _endRig, ref _endVelocityCorrection);
        }

        /// <summary>
        /// Pins (Transform end, or a Rigidbody whose mass is unusable) or loads (Rigidbody end) <paramref name="particle"/>;
        /// the id not created is -1. A pin whose pose is not finite holds the particle where it is.
        /// </summary>
        void AttachEnd(Rope rope, int slot, RopeEnd end, int particle, Vector3 origin, out int pin, out int load)
        {
            pin = load = -1;
            var kind = end.Kind;
            if (kind == RopeEndKind.Rigidbody && _guard.AcceptMass(slot, end.Body))
            {
                load = rope.AddLoad(particle, end.Body.mass);
                return;
            }
            if (kind == RopeEndKind.KinematicRig)
            {
                load = rope.AddLoad(particle, end.RigMass);
                return;
            }
            if (kind == RopeEndKind.Free) return;
            Vector3 target = PinTarget(end);
            pin = rope.AddPin(particle, _guard.AcceptPose(slot, end, target) ? target.RelativeTo(origin) : rope.GetPosition(particle), _compliance);
        }

        /// <summary>Releases the end's pin or load and attaches it again to what its fields now hold.</summary>
        void Reattach(Rope rope, int slot, RopeEnd end, int particle, Vector3 origin, ref int pin, ref int load, ref Vector3 velocityCorrection)
        {
            if (pin >= 0) rope.ReleasePin(pin);
            if (load >= 0) rope.ReleaseLoad(load);
            velocityCorrection = Vector3.zero;
            AttachEnd(rope, slot, end, particle, origin, out pin, out load);
        }

        /// <summary>Where a pin holds its end (world, m): the Transform end's Point, or the physics pose of a body pinned kinematically.</summary>
        static Vector3 PinTarget(RopeEnd end) => end.Kind == RopeEndKind.Rigidbody ? end.PhysicsPosition() : end.Point.position;

        /// <summary>Copies one end's pose into the rope; false (and nothing copied) when the pose is not finite.</summary>
        bool CopyIn(Rope rope, Vector3 origin, float deltaTime, int slot, RopeEnd end, int pin, int load, KinematicRigLoad rig)
        {
            if (pin >= 0 && end.Kind != RopeEndKind.Free)
            {
                Vector3 target = PinTarget(end);
                if (!_guard.AcceptPose(slot, end, target)) return false;
                rope.SetPinTarget(pin, target.RelativeTo(origin));
            }
            else if (load >= 0 && end.Body != null)
            {
                Vector3 point = end.PhysicsPosition();
                if (!_guard.AcceptPose(slot, end, point)) return false;
                Vector3 velocity = end.Body.GetPointVelocity(point);
                if (!(float.IsFinite(velocity.x) && float.IsFinite(velocity.y) && float.IsFinite(velocity.z))) velocity = Vector3.zero;
                rope.SetLoadState(load, point.RelativeTo(origin), velocity.ToFloat3());
            }
            else if (load >= 0 && end.Kind == RopeEndKind.KinematicRig)
            {
                Vector3 world = end.Point.position;
                if (!_guard.AcceptPose(slot, end, world)) return false;
                rig.BeforeStep(rope, load, world.RelativeTo(origin), deltaTime, PositionRounding(world));
            }
            return true;
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
        /// force in N (world) the rope applied on the attachment; zero for a free end or a pose that was not finite.
        /// </summary>
        static Vector3 ApplyForceToEnd(Rope rope, RopeEnd end, int pin, int load, bool poseValid, KinematicRigLoad rig, ref Vector3 velocityCorrection)
        {
            if (pin >= 0) return rope.GetPinForce(pin).ToVector3();
            if (load < 0) return Vector3.zero;
            if (end.Body != null) return ApplyForceToBody(rope, end, load, poseValid, ref velocityCorrection);
            if (end.Kind != RopeEndKind.KinematicRig || !poseValid) return Vector3.zero;
            rig.AfterStep(rope, load);
            return rope.GetLoadForce(load).ToVector3();
        }

        /// <summary>
        /// Two-way coupling, after the rope step: the force that brings the body (integrated by the physics engine
        /// with semi-implicit Euler) to where the rope's load particle ended, and the velocity correction that the
        /// next step adds before it reads the body back (see <see cref="Rope.GetLoadHostForce"/>).
        /// </summary>
        static Vector3 ApplyForceToBody(Rope rope, RopeEnd end, int load, bool poseValid, ref Vector3 velocityCorrection)
        {
            velocityCorrection = Vector3.zero;
            if (!poseValid) return Vector3.zero;
            Vector3 force = rope.GetLoadHostForce(load).ToVector3();
            if (end.Body.isKinematic) return force;
            end.Body.AddForceAtPosition(force, end.PhysicsPosition(), ForceMode.Force);
            velocityCorrection = rope.GetLoadHostVelocityCorrection(load).ToVector3();
            return force;
        }

        static void CorrectBodyVelocity(RopeEnd end, int load, ref Vector3 velocityCorrection)
        {
            if (load >= 0 && end != null && end.Body != null && !end.Body.isKinematic) end.Body.velocity += velocityCorrection;
            velocityCorrection = Vector3.zero;
        }
    }
}
