using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace HookeRope.Solver
{
    /// <summary>
    /// Axis-aligned bounds of the live positions (Prev + D, rope-local m) of the whole rope and of every block of
    /// <see cref="BlockSize"/> consecutive particles, with the largest particle radius of each: what the collision broad
    /// phase compares with the colliders before every collision pass. <see cref="Scan"/> bounds the rope alone (one
    /// streaming pass); the blocks are bounded only when first asked for (<see cref="Block"/>: some collider is within reach
    /// of the rope), so a rope with every collider out of reach pays one pass over its positions and nothing more.
    /// <para>Where <see cref="Vector.IsHardwareAccelerated"/> the passes run on <see cref="Vector{T}"/> lanes; elsewhere
    /// (Mono and IL2CPP may not accelerate <see cref="Vector{T}"/>) scalar loops give the same boxes.</para>
    /// <para>A NaN coordinate is left out of a box: the narrow phase's distance to such a particle is NaN, which neither
    /// pushes, nor detects, nor rubs it, so leaving it out changes nothing. ±∞ is kept, and every broad-phase test on an
    /// infinite box comes out "near". Allocation-free after <see cref="Reserve"/>.</para>
    /// </summary>
    internal sealed class ParticleBlocks
    {
        /// <summary>Particles per block (a multiple of every <see cref="Vector{T}"/> width in use).</summary>
        public const int BlockSize = 32;

        private const int LaneValues = 6; // per block on vector lanes: lo x y z, hi x y z

        private ChainState chain;
        private int particleCount, blockCount;
        private bool blocksScanned;
        private ParticleBox[] boxes = new ParticleBox[0];
        private bool[] reduced = new bool[0];
        private Vector<float>[] lanes = new Vector<float>[0];
        private float[] radii = new float[0];
        private float ropeRadius;
        private bool radiiStale = true;
        private ParticleBox rope;

        /// <summary>Scan on vector lanes where the hardware accelerates them (tests switch it off to check the scalar scans).</summary>
        public bool UseVectors { get; set; } = Vector.IsHardwareAccelerated && BlockSize % Vector<float>.Count == 0;

        /// <summary>Blocks of the last scan.</summary>
        public int BlockCount => blockCount;

        /// <summary>The whole rope's box of the last scan.</summary>
        public ParticleBox Rope => rope;

        /// <summary>Makes room for a chain of <paramref name="particles"/> (allocates only when it grows).</summary>
        public void Reserve(int particles)
        {
            int blocks = (particles + BlockSize - 1) / BlockSize;
            if (blocks <= boxes.Length) return;
            boxes = new ParticleBox[blocks];
            reduced = new bool[blocks];
            lanes = new Vector<float>[blocks * LaneValues];
            radii = new float[blocks];
            radiiStale = true;
        }

        /// <summary>
        /// Makes the next <see cref="Scan"/> read the particle radii again. They change only between host steps (the radius
        /// model, new settings), so the collision set calls this when a step ends and when a collider is added.
        /// </summary>
        public void RadiiChanged() => radiiStale = true;

        /// <summary>Bounds the whole rope of <paramref name="c"/> at its current live positions (the blocks follow on demand).</summary>
        public void Scan(ChainState c)
        {
            Reserve(c.ParticleCount);
            chain = c;
            particleCount = c.ParticleCount;
            blockCount = (particleCount + BlockSize - 1) / BlockSize;
            blocksScanned = false;
            if (radiiStale) ScanRadii(c.Radius);
            if (!(Vectors && ScanRopeVectors(c))) ScanRopeScalar(c);
        }

        /// <summary>Box of block b (particles b·<see cref="BlockSize"/> onwards) at the positions of the last <see cref="Scan"/>.</summary>
        public ParticleBox Block(int b)
        {
            if (!blocksScanned)
            {
                if (!(Vectors && ScanBlockVectors(chain))) ScanBlocksScalar(chain);
                blocksScanned = true;
            }
            if (!reduced[b])
            {
                int o = b * LaneValues;
                boxes[b] = Reduce(lanes[o], lanes[o + 1], lanes[o + 2], lanes[o + 3], lanes[o + 4], lanes[o + 5], radii[b]);
                reduced[b] = true;
            }
            return boxes[b];
        }

        private bool Vectors => UseVectors && particleCount >= Vector<float>.Count;

        private void ScanRadii(float[] radius)
        {
            ropeRadius = 0f;
            for (int b = 0; b < blockCount; b++)
            {
                int end = Math.Min((b + 1) * BlockSize, particleCount);
                float r = 0f;
                for (int i = b * BlockSize; i < end; i++) if (radius[i] > r) r = radius[i];
                radii[b] = r;
                if (r > ropeRadius) ropeRadius = r;
            }
            radiiStale = false;
        }

        private void ScanRopeScalar(ChainState c) => rope = Bound(c, 0, particleCount, ropeRadius);

        private void ScanBlocksScalar(ChainState c)
        {
            for (int b = 0; b < blockCount; b++)
            {
                boxes[b] = Bound(c, b * BlockSize, Math.Min((b + 1) * BlockSize, particleCount), radii[b]);
                reduced[b] = true;
            }
        }

        /// <summary>The box of particles start … end − 1 with radius r (a scalar loop; it calls nothing).</summary>
        private static ParticleBox Bound(ChainState c, int start, int end, float r)
        {
            float[] px = c.PrevX, py = c.PrevY, pz = c.PrevZ, dx = c.DX, dy = c.DY, dz = c.DZ;
            float lx = float.PositiveInfinity, ly = lx, lz = lx, hx = float.NegativeInfinity, hy = hx, hz = hx;
            for (int i = start; i < end; i++)
            {
                float x = px[i] + dx[i], y = py[i] + dy[i], z = pz[i] + dz[i];
                if (x < lx) lx = x;
                if (x > hx) hx = x;
                if (y < ly) ly = y;
                if (y > hy) hy = y;
                if (z < lz) lz = z;
                if (z > hz) hz = z;
            }
            return new ParticleBox(lx, ly, lz, hx, hy, hz, r);
        }

        /// <summary>The rope's box on vector lanes (the particles after the last whole vector by a scalar loop); false if the chain's arrays were not all one length.</summary>
        private bool ScanRopeVectors(ChainState c)
        {
            int full = particleCount / Vector<float>.Count * Vector<float>.Count;
            if (!StreamRange(Lanes(c.PrevX), Lanes(c.PrevY), Lanes(c.PrevZ), Lanes(c.DX), Lanes(c.DY), Lanes(c.DZ), out LaneBox all)) return false;
            rope = Reduce(all.LowX, all.LowY, all.LowZ, all.HighX, all.HighY, all.HighZ, ropeRadius);
            if (full < particleCount) rope = ParticleBox.Union(rope, Bound(c, full, particleCount, ropeRadius));
            return true;
        }

        /// <summary>Lane-wise lowest and highest coordinates.</summary>
        private struct LaneBox
        {
            public Vector<float> LowX, LowY, LowZ, HighX, HighY, HighZ;
        }

        /// <summary>
        /// Lane-wise range of prev + d over every vector of the spans. Stores nothing in the loop and calls nothing, so the
        /// compiler drops its bounds checks and compiles it fully optimised everywhere. False unless every span holds as many
        /// vectors as <paramref name="px"/>.
        /// </summary>
        private static bool StreamRange(ReadOnlySpan<Vector<float>> px, ReadOnlySpan<Vector<float>> py, ReadOnlySpan<Vector<float>> pz,
            ReadOnlySpan<Vector<float>> dx, ReadOnlySpan<Vector<float>> dy, ReadOnlySpan<Vector<float>> dz, out LaneBox range)
        {
            range = default;
            int n = px.Length;
            if (py.Length < n || pz.Length < n || dx.Length < n || dy.Length < n || dz.Length < n) return false;
            var inf = new Vector<float>(float.PositiveInfinity);
            var negInf = new Vector<float>(float.NegativeInfinity);
            Vector<float> lx = inf, ly = inf, lz = inf, hx = negInf, hy = negInf, hz = negInf;
            for (int v = 0; v < n; v++) Grow(ref lx, ref ly, ref lz, ref hx, ref hy, ref hz, px[v] + dx[v], py[v] + dy[v], pz[v] + dz[v]);
            range.LowX = lx; range.LowY = ly; range.LowZ = lz; range.HighX = hx; range.HighY = hy; range.HighZ = hz;
            return true;
        }

        /// <summary>The blocks' lane-wise ranges on vector lanes; false if the chain's arrays were not all one length.</summary>
        private bool ScanBlockVectors(ChainState c)
        {
            int n = particleCount, width = Vector<float>.Count;
            bool tail = n % width != 0;
            int at = n - width;
            // the last, short chunk is read from n − width: it overlaps the chunk before it (a larger box, never a smaller one)
            if (!BlockRanges(Lanes(c.PrevX), Lanes(c.PrevY), Lanes(c.PrevZ), Lanes(c.DX), Lanes(c.DY), Lanes(c.DZ),
                    tail ? Chunk(c.PrevX, c.DX, at) : default, tail ? Chunk(c.PrevY, c.DY, at) : default, tail ? Chunk(c.PrevZ, c.DZ, at) : default, tail))
                return false;
            Array.Clear(reduced, 0, blockCount);
            return true;
        }

        /// <summary>
        /// Each block's lane-wise range of prev + d over its whole vectors and, for the last block, the tail chunk (tx, ty, tz),
        /// kept in <see cref="lanes"/>. Calls nothing. False, having done nothing, unless every span holds as many vectors as
        /// <paramref name="px"/>.
        /// </summary>
        private bool BlockRanges(ReadOnlySpan<Vector<float>> px, ReadOnlySpan<Vector<float>> py, ReadOnlySpan<Vector<float>> pz,
            ReadOnlySpan<Vector<float>> dx, ReadOnlySpan<Vector<float>> dy, ReadOnlySpan<Vector<float>> dz,
            Vector<float> tx, Vector<float> ty, Vector<float> tz, bool hasTail)
        {
            int n = px.Length;
            if (py.Length < n || pz.Length < n || dx.Length < n || dy.Length < n || dz.Length < n) return false;
            int last = BlockSize / Vector<float>.Count - 1; // a power of two less one
            Vector<float>[] store = lanes;
            var inf = new Vector<float>(float.PositiveInfinity);
            var negInf = new Vector<float>(float.NegativeInfinity);
            Vector<float> lx = inf, ly = inf, lz = inf, hx = negInf, hy = negInf, hz = negInf;
            for (int v = 0; v < n; v++)
            {
                Grow(ref lx, ref ly, ref lz, ref hx, ref hy, ref hz, px[v] + dx[v], py[v] + dy[v], pz[v] + dz[v]);
                if ((v & last) != last) continue;
                Keep(store, v / (last + 1) * LaneValues, lx, ly, lz, hx, hy, hz);
                lx = ly = lz = inf;
                hx = hy = hz = negInf;
            }
            bool open = (n & last) != 0;
            if (hasTail)
            {
                Grow(ref lx, ref ly, ref lz, ref hx, ref hy, ref hz, tx, ty, tz);
                open = true;
            }
            if (open) Keep(store, n / (last + 1) * LaneValues, lx, ly, lz, hx, hy, hz);
            return true;
        }

        /// <summary>Grows the lane-wise range (lx … hz) over the chunk (x, y, z); a NaN lane is left out.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Grow(ref Vector<float> lx, ref Vector<float> ly, ref Vector<float> lz, ref Vector<float> hx, ref Vector<float> hy, ref Vector<float> hz,
            Vector<float> x, Vector<float> y, Vector<float> z)
        {
            lx = Vector.ConditionalSelect(Vector.LessThan(x, lx), x, lx);
            hx = Vector.ConditionalSelect(Vector.GreaterThan(x, hx), x, hx);
            ly = Vector.ConditionalSelect(Vector.LessThan(y, ly), y, ly);
            hy = Vector.ConditionalSelect(Vector.GreaterThan(y, hy), y, hy);
            lz = Vector.ConditionalSelect(Vector.LessThan(z, lz), z, lz);
            hz = Vector.ConditionalSelect(Vector.GreaterThan(z, hz), z, hz);
        }

        /// <summary>Stores a block's lane-wise range at slot o.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Keep(Vector<float>[] store, int o, Vector<float> lx, Vector<float> ly, Vector<float> lz, Vector<float> hx, Vector<float> hy, Vector<float> hz)
        {
            store[o] = lx; store[o + 1] = ly; store[o + 2] = lz; store[o + 3] = hx; store[o + 4] = hy; store[o + 5] = hz;
        }

        /// <summary>The whole vectors of <paramref name="values"/> (a short remainder is left out).</summary>
        private static ReadOnlySpan<Vector<float>> Lanes(float[] values) => MemoryMarshal.Cast<float, Vector<float>>(new ReadOnlySpan<float>(values));

        /// <summary>prev + d over the vector width of particles from <paramref name="at"/>.</summary>
        private static Vector<float> Chunk(float[] prev, float[] d, int at) =>
            MemoryMarshal.Cast<float, Vector<float>>(new ReadOnlySpan<float>(prev, at, Vector<float>.Count))[0]
          + MemoryMarshal.Cast<float, Vector<float>>(new ReadOnlySpan<float>(d, at, Vector<float>.Count))[0];

        /// <summary>The box of lane-wise ranges (lx … hz) and radius r.</summary>
        private static ParticleBox Reduce(Vector<float> lx, Vector<float> ly, Vector<float> lz, Vector<float> hx, Vector<float> hy, Vector<float> hz, float r)
        {
            float ax = lx[0], ay = ly[0], az = lz[0], bx = hx[0], by = hy[0], bz = hz[0];
            for (int i = 1; i < Vector<float>.Count; i++)
            {
                if (lx[i] < ax) ax = lx[i];
                if (ly[i] < ay) ay = ly[i];
                if (lz[i] < az) az = lz[i];
                if (hx[i] > bx) bx = hx[i];
                if (hy[i] > by) by = hy[i];
                if (hz[i] > bz) bz = hz[i];
            }
            return new ParticleBox(ax, ay, az, bx, by, bz, r);
        }
    }
}
