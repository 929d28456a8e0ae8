using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// The colliders of one rope in the rope-local frame, with the pose at the start and end of the
    /// current host step (positions are interpolated linearly, rotations by nlerp, across substeps: <see cref="ColliderPoses"/>).
    /// Particles are pushed out along the surface normal to their collision radius; friction removes
    /// tangential motion relative to the collider up to μ times the push depth (position-based Coulomb).
    /// A broad phase (<see cref="CollisionBroadPhase"/> over <see cref="ParticleBlocks"/>) limits that work to the colliders
    /// within reach of the rope and the blocks of particles within reach of each, with the brute-force pass's result to the bit.
    /// </summary>
    internal sealed class CollisionSet
    {
        /// <summary>Contact detection margin as a fraction of the particle radius: a particle this close to a surface counts as touching it.</summary>
        public const float ContactMarginFraction = 0.1f;

        private ColliderShape[] shapes = new ColliderShape[0];
        private readonly ColliderPoses poses = new ColliderPoses();
        private readonly CollisionBroadPhase broad = new CollisionBroadPhase();
        private readonly ParticleBlocks blocks = new ParticleBlocks();
        private bool[] nearRope = new bool[0], candidate = new bool[0];
        private double[] candidateReach = new double[0]; // the block's reach of each candidate collider (see CollisionBroadPhase.Reach)
        private int[] boundSubstep = new int[0]; // the substep whose bound the broad phase holds for each collider
        private int substep;                     // serial number of the current substep
        private bool swept;                      // the broad phase holds every collider's bound over this host step

        public int Count { get; private set; }

        /// <summary>Uses the brute-force pass (every dynamic particle against every collider) instead of the broad phase: the reference the broad phase is tested against.</summary>
        internal bool BruteForce { get; set; }

        /// <summary>The particle blocks of the broad phase (tests switch their vector scan off).</summary>
        internal ParticleBlocks Blocks => blocks;

        /// <summary>Particle–collider pairs the narrow phase has evaluated so far (tests check that the broad phase spares the rest).</summary>
        internal long PairsResolved { get; private set; }

        public int Add(in ColliderShape shape, Float3 localPosition)
        {
            if (Count == shapes.Length)
            {
                int size = ArrayGrowth.NextCapacity(Count);
                Array.Resize(ref shapes, size);
                poses.Resize(size);
                Array.Resize(ref nearRope, size);
                Array.Resize(ref candidate, size);
                Array.Resize(ref candidateReach, size);
                Array.Resize(ref boundSubstep, size);
            }
            int i = Count++;
            shapes[i] = shape;
            poses.Place(i, localPosition, shape.Rotation);
            boundSubstep[i] = substep - 1;
            swept = false;
            blocks.RadiiChanged();
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
                Array.Copy(boundSubstep, i + 1, boundSubstep, i, tail);
            }
            poses.RemoveAt(i, Count);
            Count--;
            shapes[Count] = default;
            swept = false;
        }

        /// <summary>Removes every collider (the arrays are kept for reuse).</summary>
        public void Clear()
        {
            for (int i = 0; i < Count; i++) shapes[i] = default;
            Count = 0;
        }

        public void SetPose(int i, Float3 localPosition, Quat newRotation)
        {
            poses.SetEnd(i, localPosition, newRotation.Normalized());
            swept = false;
        }

        /// <summary>Pose at fraction t ∈ (0, 1] of the host step of length dt (s) (worked out for the colliders that need it).</summary>
        public void PrepareSubstep(float t, float dt)
        {
            poses.BeginSubstep(t, dt);
            substep++;
        }

        /// <summary>Makes room in the broad phase for a chain of <paramref name="particles"/> (when a collider is added; never in a step).</summary>
        public void Reserve(int particles)
        {
            blocks.Reserve(particles);
            broad.Reserve(shapes.Length);
        }

        /// <summary>Makes the end pose of this host step the start pose of the next.</summary>
        public void EndStep()
        {
            poses.EndStep(Count);
            blocks.RadiiChanged();
            swept = false;
        }

        /// <summary>
        /// Pushes every dynamic particle out of every collider (substep h in s). What else the pass does depends on where
        /// in the substep it runs (<see cref="ContactPass"/>): before the last iteration it records for each particle the
        /// closest surface within <see cref="ContactMarginFraction"/>·radius (normal, gap) as the contact set of the next
        /// chain solve, and at the start of the substep it also resets the per-substep normal corrections; after the last
        /// iteration it applies Coulomb friction instead, limited by μ times the particle's whole normal correction in
        /// this substep (<see cref="ChainState.ContactLoad"/>: pushes plus the normal motion the chain solve's
        /// tangent-plane mass withheld).
        /// <para>Every push adds m·push·normal to the particle's contact impulse (<see cref="ChainState.ContactImpulseX"/>).
        /// With <paramref name="frictionInSolve"/> (the exact chain solve) friction is part of the solve instead: a contact that
        /// was sticking or sliding at the last detection starts so again, a new one gets its friction state from the solve
        /// (see <see cref="ChainContacts"/>), and the pass applies no friction of its own.</para>
        /// <para>The broad phase bounds the particles (<see cref="ParticleBlocks.Scan"/>), rules out the colliders whose path
        /// over the host step is out of reach of the whole rope, works out the substep pose and bound of the others, and
        /// passes to the narrow phase only the blocks of particles within reach of one of them. The result is the
        /// brute-force pass's (<see cref="BruteForce"/>) to the bit.</para>
        /// </summary>
        public void Project(ChainState c, float h, ContactPass pass, bool frictionInSolve)
        {
            bool detect = pass != ContactPass.LastIteration;
            passFrictionInSolve = frictionInSolve;
            passStart = pass == ContactPass.StartOfSubstep;
            passStep = h;
            if (passStart)
            {
                int n = c.ParticleCount;
                Array.Clear(c.ContactImpulseX, 0, n); Array.Clear(c.ContactImpulseY, 0, n); Array.Clear(c.ContactImpulseZ, 0, n);
                Array.Clear(c.ContactFrictionX, 0, n); Array.Clear(c.ContactFrictionY, 0, n); Array.Clear(c.ContactFrictionZ, 0, n);
                Array.Clear(c.ContactStopped, 0, n);
            }
            if (detect) RememberContacts(c);
            ProjectPass(c, h, pass, detect, pass == ContactPass.LastIteration && !frictionInSolve);
            if (detect) Array.Clear(c.ContactMemory, 0, c.ParticleCount);
        }

        private bool passFrictionInSolve, passStart; // the current pass's: friction in the chain solve, start of a substep
        private float passStep;                       // s, the current pass's substep

        private void ProjectPass(ChainState c, float h, ContactPass pass, bool detect, bool friction)
        {
            float[] load = c.ContactLoad;
            if (BruteForce)
            {
                ProjectEveryPair(c, h, pass == ContactPass.StartOfSubstep, detect, friction, load);
                return;
            }
            if (pass == ContactPass.StartOfSubstep) Array.Clear(load, 0, c.ParticleCount);
            blocks.Scan(c);
            if (!NearColliders(blocks.Rope)) return;
            for (int b = 0; b < blocks.BlockCount; b++)
            {
                ParticleBox box = blocks.Block(b);
                bool blockNear = false;
                for (int k = 0; k < Count; k++)
                {
                    candidate[k] = false;
                    if (!nearRope[k]) continue;
                    candidateReach[k] = broad.Reach(k, box, false);
                    candidate[k] = broad.Within(k, box, candidateReach[k], false);
                    blockNear |= candidate[k];
                }
                if (blockNear) ProjectBlock(c, b, h, detect, friction, load);
            }
        }

        /// <summary>
        /// Marks the colliders within reach of the rope's box (<see cref="nearRope"/>) and works out their pose and bound for the
        /// substep. Returns whether there is any.
        /// </summary>
        private bool NearColliders(in ParticleBox rope)
        {
            broad.Reserve(Count);
            if (!swept)
            {
                for (int k = 0; k < Count; k++)
                    broad.SetSweep(k, shapes[k], poses.StartPosition(k), poses.EndPosition(k), poses.StartRotation(k), poses.EndRotation(k));
                swept = true;
            }
            bool any = false;
            for (int k = 0; k < Count; k++)
            {
                nearRope[k] = broad.Near(k, rope, true);
                if (!nearRope[k]) continue;
                BoundSubstep(k);
                nearRope[k] = broad.Near(k, rope, false);
                any |= nearRope[k];
            }
            return any;
        }

        /// <summary>Works out collider k's pose in this substep and gives the broad phase its bound, once per substep.</summary>
        private void BoundSubstep(int k)
        {
            poses.Ensure(k);
            if (boundSubstep[k] == substep) return;
            broad.SetPose(k, shapes[k], poses.Position(k), poses.Rotation(k));
            boundSubstep[k] = substep;
        }

        /// <summary>The box of particle i's live position and radius r (m).</summary>
        private static ParticleBox Here(ChainState c, int i, float r) => ParticleBox.Point(c.PrevX[i] + c.DX[i], c.PrevY[i] + c.DY[i], c.PrevZ[i] + c.DZ[i], r);

        /// <summary>The narrow phase for the dynamic particles of block b within reach of a collider within reach of the block (<see cref="candidate"/>).</summary>
        private void ProjectBlock(ChainState c, int b, float h, bool detect, bool friction, float[] load)
        {
            int end = Math.Min(c.ParticleCount, (b + 1) * ParticleBlocks.BlockSize);
            for (int i = b * ParticleBlocks.BlockSize; i < end; i++)
            {
                if (c.InverseMass[i] == 0f) continue;
                float r = c.Radius[i];
                var best = new ClosestContact(ContactMarginFraction * r);
                bool moved = false;
                for (int k = 0; k < Count; k++)
                {
                    if (moved)
                    {
                        // a particle this pass has moved (push, friction) may have come within reach of any later collider
                        if (!broad.Near(k, Here(c, i, r), true)) continue;
                        BoundSubstep(k);
                        if (!broad.Near(k, Here(c, i, r), false)) continue;
                    }
                    else if (!candidate[k] || !broad.Within(k, Here(c, i, r), candidateReach[k], false))
                    {
                        // the block's reach holds for each of its particles
                        continue;
                    }
                    moved |= Resolve(c, i, k, r, h, detect, friction, load, ref best);
                }
                if (detect && best.Found) AddContact(c, i, best.Collider, best.Normal, best.Gap);
            }
        }

        /// <summary>Every dynamic particle against every collider: what <see cref="Project"/> does, without the broad phase.</summary>
        private void ProjectEveryPair(ChainState c, float h, bool startOfSubstep, bool detect, bool friction, float[] load)
        {
            for (int k = 0; k < Count; k++) poses.Ensure(k);
            for (int i = 0; i < c.ParticleCount; i++)
            {
                if (startOfSubstep) load[i] = 0f;
                if (c.InverseMass[i] == 0f) continue;
                float r = c.Radius[i];
                var best = new ClosestContact(ContactMarginFraction * r);
                for (int k = 0; k < Count; k++) Resolve(c, i, k, r, h, detect, friction, load, ref best);
                if (detect && best.Found) AddContact(c, i, best.Collider, best.Normal, best.Gap);
            }
        }

        /// <summary>
        /// Particle i (radius r, m) against collider k: pushes it out, offers the surface as its contact when detecting, and
        /// applies friction on the last iteration. Returns true when it wrote the particle's displacement.
        /// </summary>
        private bool Resolve(ChainState c, int i, int k, float r, float h, bool detect, bool friction, float[] load, ref ClosestContact best)
        {
            PairsResolved++;
            var d = new Float3(c.DX[i], c.DY[i], c.DZ[i]);
            var x = new Float3(c.PrevX[i], c.PrevY[i], c.PrevZ[i]) + d;
            float distance = SignedDistance(k, x, out Float3 normal);
            float push = r - distance;
            if (detect) best.Offer(k, push > 0f ? 0f : -push, normal);
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
                return false;
            }
            // friction also acts where the chain solve held the particle on the surface (no push left)
            if (friction && shapes[k].Friction > 0f)
            {
                Float3 moved = d - poses.Velocity(k) * h;
                Float3 tangent = moved - normal * Float3.Dot(moved, normal);
                float slide = tangent.Length;
                float limit = shapes[k].Friction * load[i];
                if (slide > 0f) d -= slide <= limit ? tangent : tangent * (limit / slide);
            }
            c.DX[i] = d.X; c.DY[i] = d.Y; c.DZ[i] = d.Z;
            return true;
        }

        /// <summary>The closest surface offered to one particle in a detecting pass (gap in m, within the contact margin).</summary>
        private struct ClosestContact
        {
            private float gap;
            private int collider;
            private Float3 normal;

            public ClosestContact(float margin)
            {
                gap = margin;
                collider = -1;
                normal = Float3.Zero;
            }

            public void Offer(int k, float candidateGap, Float3 candidateNormal)
            {
                if (candidateGap <= gap && (collider < 0 || candidateGap < gap))
                {
                    gap = candidateGap;
                    collider = k;
                    normal = candidateNormal;
                }
            }

            /// <summary>A surface (with a finite normal) was offered.</summary>
            public bool Found => collider >= 0 && float.IsFinite(normal.X + normal.Y + normal.Z);
            public int Collider => collider;
            public Float3 Normal => normal;
            public float Gap => gap;
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
        private void AddContact(ChainState c, int i, int k, Float3 normal, float gap)
        {
            bool frictionInSolve = passFrictionInSolve;
            c.ContactCollider[i] = k;
            // touching (pushed out) or held in the iteration before: held; else within the margin: free until the chain
            // drives it onto the surface
            byte memory = c.ContactMemory[i];
            c.ContactActive[i] = gap <= 0f || !frictionInSolve || !passStart && memory != 0;
            c.ContactNX[i] = normal.X; c.ContactNY[i] = normal.Y; c.ContactNZ[i] = normal.Z;
            c.ContactGap[i] = gap;
            c.ContactList[c.ContactCount++] = i;
            float kinetic = shapes[k].Friction, stat = Math.Max(shapes[k].StaticFriction, kinetic);
            c.ContactKineticFriction[i] = kinetic;
            c.ContactStaticFriction[i] = stat;
            Float3 surface = poses.Velocity(k) * passStep;
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
            Float3 centre = poses.Position(k);
            Quat q = poses.Rotation(k);
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
