using HookeRope.Solver;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// Couples the two ends of an <see cref="ElasticRope"/> with Unity: pins the end particles to Transforms (an
    /// anchor, an XR hand) or loads them with Rigidbodies (two-way). Before each rope step it applies the pending
    /// velocity correction to the bodies and copies the attachment poses in; after the step it applies the rope's
    /// force to the bodies (semi-implicit Euler, see <see cref="Rope.GetLoadHostForce"/>). Positions go into the
    /// rope's frame: world axes, origin at the origin passed in (m). Allocation-free per step.
    /// </summary>
    internal sealed class RopeAttachmentBinding
    {
        RopeEnd _start, _end;
        int _startPin = -1, _endPin = -1, _startLoad = -1, _endLoad = -1;
        Vector3 _startVelocityCorrection, _endVelocityCorrection;

        /// <summary>The load id of the end Rigidbody, or -1 when the end is not a Rigidbody.</summary>
        public int EndLoad => _endLoad;

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
        }

        /// <summary>
        /// Before a rope step: adds the velocity corrections of the last step to the bodies, then copies the
        /// Transform targets and the body positions and velocities into <paramref name="rope"/>.
        /// </summary>
        public void CopyIn(Rope rope, Vector3 origin)
        {
            CorrectBodyVelocity(_start, ref _startVelocityCorrection);
            CorrectBodyVelocity(_end, ref _endVelocityCorrection);
            CopyIn(rope, origin, _start, _startPin, _startLoad);
            CopyIn(rope, origin, _end, _endPin, _endLoad);
        }

        /// <summary>After a rope step: applies the rope's force to the attached bodies and keeps the velocity corrections for the next step.</summary>
        public void ApplyForces(Rope rope)
        {
            ApplyForceToBody(rope, _start, _startLoad, ref _startVelocityCorrection);
            ApplyForceToBody(rope, _end, _endLoad, ref _endVelocityCorrection);
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
            }
        }

        static void CopyIn(Rope rope, Vector3 origin, RopeEnd end, int pin, int load)
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
        }

        /// <summary>
        /// Two-way coupling, after the rope step: the force that brings the body (integrated by the physics engine
        /// with semi-implicit Euler) to where the rope's load particle ended, and the velocity correction that the
        /// next step adds before it reads the body back (see <see cref="Rope.GetLoadHostForce"/>).
        /// </summary>
        static void ApplyForceToBody(Rope rope, RopeEnd end, int load, ref Vector3 velocityCorrection)
        {
            velocityCorrection = Vector3.zero;
            if (load < 0 || end.Body == null || end.Body.isKinematic) return;
            Vector3 force = rope.GetLoadHostForce(load).ToVector3();
            end.Body.AddForceAtPosition(force, end.PhysicsPosition(), ForceMode.Force);
            velocityCorrection = rope.GetLoadHostVelocityCorrection(load).ToVector3();
        }

        static void CorrectBodyVelocity(RopeEnd end, ref Vector3 velocityCorrection)
        {
            if (end != null && end.Body != null && !end.Body.isKinematic) end.Body.velocity += velocityCorrection;
            velocityCorrection = Vector3.zero;
        }
    }
}
