using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// The colliders of one rope in the rope-local frame, with the pose at the start and end of the
    /// current host step (positions are interpolated linearly, rotations by nlerp, across substeps).
    /// Particles are pushed out along the surface normal to their collision radius; friction removes
    /// tangential motion relative to the collider up to μ times the push depth (position-based Coulomb).
    /// </summary>
    internal sealed class CollisionSet
    {
        private ColliderShape[] shapes = new ColliderShape[0];
        private Float3[] startPosition = new Float3[0], endPosition = new Float3[0], position = new Float3[0], velocity = new Float3[0];
        private Quat[] startRotation = new Quat[0], endRotation = new Quat[0], rotation = new Quat[0];

        public int Count { get; private set; }

        public int Add(in ColliderShape shape, Float3 localPosition)
        {
            if (Count == shapes.Length)
            {
                int size = ArrayGrowth.NextCapacity(Count);
                Array.Resize(ref shapes, size);
                Array.Resize(ref startPosition, size);
                Array.Resize(ref endPosition, size);
                Array.Resize(ref position, size);
                Array.Resize(ref velocity, size);
                Array.Resize(ref startRotation, size);
                Array.Resize(ref endRotation, size);
                Array.Resize(ref rotation, size);
            }
            int i = Count++;
            shapes[i] = shape;
            startPosition[i] = endPosition[i] = position[i] = localPosition;
            startRotation[i] = endRotation[i] = rotation[i] = shape.Rotation;
            velocity[i] = Float3.Zero;
            return i;
        }

        public ColliderShape Get(int i) => shapes[i];

        /// <summary>Removes collider i; the colliders after it move down one index. Allocation-free.</summary>
        public void RemoveAt(int i)
        {
            int tail = Count - i - 1;
            if (tail > 0)
            {
                Array.Copy(shapes, i + 1, shapes, i, tail);
                Array.Copy(startPosition, i + 1, startPosition, i, tail);
                Array.Copy(endPosition, i + 1, endPosition, i, tail);
                Array.Copy(position, i + 1, position, i, tail);
                Array.Copy(velocity, i + 1, velocity, i, tail);
                Array.Copy(startRotation, i + 1, startRotation, i, tail);
                Array.Copy(endRotation, i + 1, endRotation, i, tail);
                Array.Copy(rotation, i + 1, rotation, i, tail);
            }
            Count--;
            shapes[Count] = default;
        }

        /// <summary>Removes every collider (the arrays are kept for reuse).</summary>
        public void Clear()
        {
            for (int i = 0; i < Count; i++) shapes[i] = default;
            Count = 0;
        }

        public void SetPose(int i, Float3 localPosition, Quat newRotation)
        {
            endPosition[i] = localPosition;
            endRotation[i] = newRotation.Normalized();
        }

        /// <summary>Pose at fraction t ∈ (0, 1] of the host step of length dt (s).</summary>
        public void PrepareSubstep(float t, float dt)
        {
            for (int i = 0; i < Count; i++)
            {
                position[i] = Float3.Lerp(startPosition[i], endPosition[i], t);
                rotation[i] = t >= 1f ? endRotation[i] : Quat.Nlerp(startRotation[i], endRotation[i], t);
                velocity[i] = (endPosition[i] - startPosition[i]) / dt;
            }
        }

        /// <summary>Makes the end pose of this host step the start pose of the next.</summary>
        public void EndStep()
        {
            for (int i = 0; i < Count; i++)
            {
                startPosition[i] = endPosition[i];
                startRotation[i] = endRotation[i];
                velocity[i] = Float3.Zero;
            }
        }

        /// <summary>Contact detection margin as a fraction of the particle radius: a particle this close to a surface counts as touching it.</summary>
        public const float ContactMarginFraction = 0.1f;

        /// <summary>
        /// Pushes every dynamic particle out of every collider (substep h in s). What else the pass does depends on where
        /// in the substep it runs (<see cref="ContactPass"/>): before the last iteration it records for each particle the
        /// closest surface within <see cref="ContactMarginFraction"/>·radius (normal, gap, friction coefficients, the
        /// collider's displacement over the substep) as the contact set of the next chain solve, and at the start of the
        /// substep it also resets the per-substep normal corrections and contact impulses. Every push adds m·push·normal to
        /// the particle's contact impulse (<see cref="ChainState.ContactImpulseX"/>).
        /// With <paramref name="frictionInSolve"/> (the exact chain solve) friction is part of the solve: a contact that was
        /// sticking or sliding at the last detection starts so again, a new one gets its friction state from the solve (see
        /// <see cref="ChainContacts"/>). Without it (Gauss–Seidel) every contact starts held, and after the last
        /// iteration Coulomb friction is applied here instead, limited by μ times the particle's whole normal correction in
        /// this substep (<see cref="ChainState.ContactLoad"/>: pushes plus the normal motion the chain solve's tangent-plane
        /// mass withheld).
        /// </summary>
        public void Project(ChainState c, float h, ContactPass pass, bool frictionInSolve)
        {
            bool friction = pass == ContactPass.LastIteration && !frictionInSolve;
            bool detect = pass != ContactPass.LastIteration;
            bool startOfSubstep = pass == ContactPass.StartOfSubstep;
            int n = c.ParticleCount;
            float[] load = c.ContactLoad;
            if (startOfSubstep)
            {
                Array.Clear(c.ContactImpulseX, 0, n);
                Array.Clear(c.ContactImpulseY, 0, n);
                Array.Clear(c.ContactImpulseZ, 0, n);
                Array.Clear(c.ContactFrictionX, 0, n);
                Array.Clear(c.ContactFrictionY, 0, n);
                Array.Clear(c.ContactFrictionZ, 0, n);
                Array.Clear(c.ContactStopped, 0, n);
            }
            if (detect) RememberContacts(c);
            for (int i = 0; i < n; i++)
            {
                if (startOfSubstep) load[i] = 0f;
                if (c.InverseMass[i] == 0f) { if (detect) c.ContactMemory[i] = 0; continue; }
                float r = c.Radius[i];
                float bestGap = ContactMarginFraction * r;
                int best = -1;
                Float3 bestNormal = Float3.Zero;
                for (int k = 0; k < Count; k++)
                {
                    var d = new Float3(c.DX[i], c.DY[i], c.DZ[i]);
                    var x = new Float3(c.PrevX[i], c.PrevY[i], c.PrevZ[i]) + d;
                    float distance = SignedDistance(k, x, out Float3 normal);
                    float push = r - distance;
                    if (detect)
                    {
                        float gap = push > 0f ? 0f : -push;
                        if (gap <= bestGap && (best < 0 || gap < bestGap)) { bestGap = gap; best = k; bestNormal = normal; }
                    }
                    bool touching = push > 0f;
                    if (touching)
                    {
                        d += normal * push;
                        load[i] += push;
                        double impulse = c.ContactImpulseScale * c.Mass[i] * push;
                        c.ContactImpulseX[i] += impulse * normal.X; c.ContactImpulseY[i] += impulse * normal.Y; c.ContactImpulseZ[i] += impulse * normal.Z;
                    }
                    else if (!friction || c.ContactCollider[i] != k || -push > ContactMarginFraction * r)
                    {
                        continue;
                    }
                    // friction also acts where the chain solve held the particle on the surface (no push left)
                    if (friction && shapes[k].Friction > 0f)
                    {
                        Float3 moved = d - velocity[k] * h;
                        Float3 tangent = moved - normal * Float3.Dot(moved, normal);
                        float slide = tangent.Length;
                        float limit = shapes[k].Friction * load[i];
                        if (slide > 0f) d -= slide <= limit ? tangent : tangent * (limit / slide);
                    }
                    c.DX[i] = d.X; c.DY[i] = d.Y; c.DZ[i] = d.Z;
                }
                if (!detect) continue;
                if (best >= 0 && float.IsFinite(bestNormal.X + bestNormal.Y + bestNormal.Z))
                    AddContact(c, i, best, bestNormal, bestGap, h, frictionInSolve, startOfSubstep);
                c.ContactMemory[i] = 0;
            }
        }

        /// <summary>
        /// Before a detection: the state of every contact of the set about to be replaced (1 held, 2 sticking, 3 sliding) into
        /// <see cref="ChainState.ContactMemory"/> (the detection reads it for the new set and clears it), then the set is cleared.
        /// </summary>
        private static void RememberContacts(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                c.ContactMemory[i] = !c.ContactActive[i] ? (byte)0 : c.ContactSticking[i] ? (byte)2 : c.ContactSliding[i] ? (byte)3 : (byte)1;
            }
            c.ClearContacts();
        }

        /// <summary>Adds particle i's contact with collider k (outward normal, gap in m) to the set, in its initial state (see <see cref="ChainContacts"/>).</summary>
        private void AddContact(ChainState c, int i, int k, Float3 normal, float gap, float h, bool frictionInSolve, bool startOfSubstep)
        {
            c.ContactCollider[i] = k;
            // touching (pushed out) or held in the iteration before: held; else within the margin: free until the chain
            // drives it onto the surface
            byte memory = c.ContactMemory[i];
            c.ContactActive[i] = gap <= 0f || !frictionInSolve || !startOfSubstep && memory != 0;
            c.ContactNX[i] = normal.X; c.ContactNY[i] = normal.Y; c.ContactNZ[i] = normal.Z;
            c.ContactGap[i] = gap;
            c.ContactList[c.ContactCount++] = i;
            float kinetic = shapes[k].Friction, stat = Math.Max(shapes[k].StaticFriction, kinetic);
            c.ContactKineticFriction[i] = kinetic;
            c.ContactStaticFriction[i] = stat;
            Float3 surface = velocity[k] * h;
            c.ContactSurfaceX[i] = surface.X; c.ContactSurfaceY[i] = surface.Y; c.ContactSurfaceZ[i] = surface.Z;
            // a held contact keeps its friction state from one detection to the next (see ChainContacts.DecideFriction); a new
            // one has none until the chain solve's first pass gives it one
            c.ContactSticking[i] = frictionInSolve && memory == 2;
            c.ContactSliding[i] = frictionInSolve && memory == 3;
        }

        /// <summary>Signed distance (m) from point x (rope-local) to the surface of collider k, and the outward unit normal.</summary>
        public float SignedDistance(int k, Float3 x, out Float3 normal)
        {
            ref readonly ColliderShape shape = ref shapes[k];
            Float3 centre = position[k];
            Quat q = rotation[k];
            switch (shape.Kind)
            {
                case ColliderKind.Plane:
                    normal = q.Rotate(new Float3(0f, 1f, 0f));
                    return Float3.Dot(x - centre, normal);
                case ColliderKind.Sphere:
                    return Round(x - centre, shape.Radius, q, out normal);
                case ColliderKind.Capsule:
                {
                    Float3 axis = q.Rotate(new Float3(0f, 1f, 0f));
                    float t = Float3.Dot(x - centre, axis);
                    t = t < -shape.HalfHeight ? -shape.HalfHeight : (t > shape.HalfHeight ? shape.HalfHeight : t);
                    return Round(x - (centre + axis * t), shape.Radius, q, out normal);
                }
                default:
                    return BoxDistance(x - centre, q, shape.HalfExtents, out normal);
            }
        }

        private static float Round(Float3 offset, float radius, Quat q, out Float3 normal)
        {
            float dist = offset.Length;
            normal = dist > 1e-12f ? offset / dist : q.Rotate(new Float3(0f, 1f, 0f));
            return dist - radius;
        }

        private static float BoxDistance(Float3 offset, Quat q, Float3 e, out Float3 normal)
        {
            Float3 p = q.Conjugate.Rotate(offset);
            float dx = MathF.Abs(p.X) - e.X, dy = MathF.Abs(p.Y) - e.Y, dz = MathF.Abs(p.Z) - e.Z;
            if (dx <= 0f && dy <= 0f && dz <= 0f)
            {
                Float3 local;
                float d;
                if (dx >= dy && dx >= dz) { d = dx; local = new Float3(p.X >= 0f ? 1f : -1f, 0f, 0f); }
                else if (dy >= dz) { d = dy; local = new Float3(0f, p.Y >= 0f ? 1f : -1f, 0f); }
                else { d = dz; local = new Float3(0f, 0f, p.Z >= 0f ? 1f : -1f); }
                normal = q.Rotate(local);
                return d;
            }
            var outside = new Float3(MathF.Max(dx, 0f) * Sign(p.X), MathF.Max(dy, 0f) * Sign(p.Y), MathF.Max(dz, 0f) * Sign(p.Z));
            float length = outside.Length;
            normal = q.Rotate(outside / length);
            return length;
        }

        private static float Sign(float v) => v >= 0f ? 1f : -1f;
    }
}
