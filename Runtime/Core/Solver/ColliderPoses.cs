using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// Poses (rope-local m, unit rotations) of a rope's colliders at the start and end of the current host step and in its
    /// current substep: the position interpolated linearly, the rotation by nlerp, the velocity the mean over the step.
    /// The substep pose of a collider is worked out only when it is asked for (<see cref="Ensure"/>), so a collider the
    /// broad phase rules out costs nothing per substep; the numbers are those of computing every pose every substep, to
    /// the bit. Allocation-free except when a collider beyond the largest count so far is added.
    /// </summary>
    internal sealed class ColliderPoses
    {
        private Float3[] startPosition = new Float3[0], endPosition = new Float3[0], position = new Float3[0], velocity = new Float3[0];
        private Quat[] startRotation = new Quat[0], endRotation = new Quat[0], rotation = new Quat[0];
        private int[] stamp = new int[0]; // the substep whose pose position/rotation/velocity hold
        private int substep;              // serial number of the current substep
        private float fraction = 1f, stepLength = 1f;

        /// <summary>Grows the arrays to <paramref name="size"/> colliders.</summary>
        public void Resize(int size)
        {
            Array.Resize(ref startPosition, size);
            Array.Resize(ref endPosition, size);
            Array.Resize(ref position, size);
            Array.Resize(ref velocity, size);
            Array.Resize(ref startRotation, size);
            Array.Resize(ref endRotation, size);
            Array.Resize(ref rotation, size);
            Array.Resize(ref stamp, size);
        }

        /// <summary>Collider i starts, ends and is at <paramref name="localPosition"/> with rotation <paramref name="q"/>, at rest.</summary>
        public void Place(int i, Float3 localPosition, Quat q)
        {
            startPosition[i] = endPosition[i] = position[i] = localPosition;
            startRotation[i] = endRotation[i] = rotation[i] = q;
            velocity[i] = Float3.Zero;
            stamp[i] = substep;
        }

        /// <summary>Moves the poses of colliders i + 1 … count − 1 down one index.</summary>
        public void RemoveAt(int i, int count)
        {
            int tail = count - i - 1;
            if (tail <= 0) return;
            Array.Copy(startPosition, i + 1, startPosition, i, tail);
            Array.Copy(endPosition, i + 1, endPosition, i, tail);
            Array.Copy(position, i + 1, position, i, tail);
            Array.Copy(velocity, i + 1, velocity, i, tail);
            Array.Copy(startRotation, i + 1, startRotation, i, tail);
            Array.Copy(endRotation, i + 1, endRotation, i, tail);
            Array.Copy(rotation, i + 1, rotation, i, tail);
            Array.Copy(stamp, i + 1, stamp, i, tail);
        }

        /// <summary>The pose collider i reaches at the end of the host step.</summary>
        public void SetEnd(int i, Float3 localPosition, Quat q)
        {
            endPosition[i] = localPosition;
            endRotation[i] = q;
        }

        /// <summary>Starts the substep at fraction t ∈ (0, 1] of the host step of length dt (s); poses follow on demand.</summary>
        public void BeginSubstep(float t, float dt)
        {
            substep++;
            fraction = t;
            stepLength = dt;
        }

        /// <summary>Works out collider i's pose in the current substep, once.</summary>
        public void Ensure(int i)
        {
            if (stamp[i] == substep) return;
            float t = fraction;
            position[i] = Float3.Lerp(startPosition[i], endPosition[i], t);
            rotation[i] = t >= 1f ? endRotation[i] : Quat.Nlerp(startRotation[i], endRotation[i], t);
            velocity[i] = (endPosition[i] - startPosition[i]) / stepLength;
            stamp[i] = substep;
        }

        /// <summary>Makes the end pose of this host step the start pose of the next (the poses of the last substep are worked out first).</summary>
        public void EndStep(int count)
        {
            for (int i = 0; i < count; i++)
            {
                Ensure(i);
                startPosition[i] = endPosition[i];
                startRotation[i] = endRotation[i];
                velocity[i] = Float3.Zero;
            }
        }

        /// <summary>Position (rope-local m) of collider i in the current substep, or its last one (call <see cref="Ensure"/> in a step).</summary>
        public Float3 Position(int i) => position[i];

        /// <summary>Rotation of collider i in the current substep (see <see cref="Position"/>).</summary>
        public Quat Rotation(int i) => rotation[i];

        /// <summary>Velocity (m/s) of collider i over the current host step.</summary>
        public Float3 Velocity(int i) => velocity[i];

        /// <summary>Position (rope-local m) of collider i at the start of the host step.</summary>
        public Float3 StartPosition(int i) => startPosition[i];

        /// <summary>Position (rope-local m) of collider i at the end of the host step.</summary>
        public Float3 EndPosition(int i) => endPosition[i];

        /// <summary>Rotation of collider i at the start of the host step.</summary>
        public Quat StartRotation(int i) => startRotation[i];

        /// <summary>Rotation of collider i at the end of the host step.</summary>
        public Quat EndRotation(int i) => endRotation[i];
    }
}
