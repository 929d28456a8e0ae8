using System;
using System.Collections.Generic;
using HookeRope.Geometry;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>Topology and geometry measurements of a built mesh, for the tests.</summary>
    internal static class MeshChecks
    {
        /// <summary>Maps every vertex to the first vertex with exactly the same position.</summary>
        public static int[] Weld(TubeVertex[] vertices, int count)
        {
            var first = new Dictionary<(float, float, float), int>();
            var map = new int[count];
            for (int i = 0; i < count; i++)
            {
                var key = (vertices[i].PX, vertices[i].PY, vertices[i].PZ);
                if (!first.TryGetValue(key, out int w)) { w = i; first.Add(key, i); }
                map[i] = w;
            }
            return map;
        }

        /// <summary>
        /// Welds by position, then counts: distinct vertices V, undirected edges E, triangles F; edges not shared
        /// by exactly two triangles; directed edges used twice (inconsistent winding).
        /// </summary>
        public static void Topology(TubeVertex[] vertices, int vertexCount, int[] indices, int start, int count,
            out int v, out int e, out int f, out int badEdges, out int badDirections)
        {
            int[] map = Weld(vertices, vertexCount);
            var used = new HashSet<int>();
            var undirected = new Dictionary<(int, int), int>();
            var directed = new Dictionary<(int, int), int>();
            f = count / 3;
            for (int t = start; t < start + count; t += 3)
            {
                for (int s = 0; s < 3; s++)
                {
                    int a = map[indices[t + s]], b = map[indices[t + (s + 1) % 3]];
                    used.Add(a);
                    var key = a < b ? (a, b) : (b, a);
                    undirected.TryGetValue(key, out int c);
                    undirected[key] = c + 1;
                    directed.TryGetValue((a, b), out int d);
                    directed[(a, b)] = d + 1;
                }
            }
            v = used.Count;
            e = undirected.Count;
            badEdges = 0;
            foreach (var pair in undirected) if (pair.Value != 2) badEdges++;
            badDirections = 0;
            foreach (var pair in directed) if (pair.Value != 1) badDirections++;
        }

        /// <summary>Signed volume in m³ enclosed by the triangles (positive for outward winding).</summary>
        public static double Volume(TubeVertex[] vertices, int[] indices, int start, int count)
        {
            double sum = 0.0;
            for (int t = start; t < start + count; t += 3)
            {
                TubeVertex a = vertices[indices[t]], b = vertices[indices[t + 1]], c = vertices[indices[t + 2]];
                double cx = (double)b.PY * c.PZ - (double)b.PZ * c.PY;
                double cy = (double)b.PZ * c.PX - (double)b.PX * c.PZ;
                double cz = (double)b.PX * c.PY - (double)b.PY * c.PX;
                sum += a.PX * cx + a.PY * cy + a.PZ * cz;
            }
            return sum / 6.0;
        }

        /// <summary>The winding normal Cross(b − a, c − a) of triangle a, b, c (its length is twice the area, m²).</summary>
        private static void Winding(in TubeVertex a, in TubeVertex b, in TubeVertex c, out double nx, out double ny, out double nz)
        {
            double ux = b.PX - a.PX, uy = b.PY - a.PY, uz = b.PZ - a.PZ;
            double wx = c.PX - a.PX, wy = c.PY - a.PY, wz = c.PZ - a.PZ;
            nx = uy * wz - uz * wy; ny = uz * wx - ux * wz; nz = ux * wy - uy * wx;
        }

        /// <summary>Smallest triangle area in m² and the smallest cosine between a face normal (from the winding) and its vertices' normals.</summary>
        public static void Faces(TubeVertex[] vertices, int[] indices, int start, int count, out double smallestArea, out double worstAlignment)
        {
            smallestArea = double.MaxValue;
            worstAlignment = 1.0;
            for (int t = start; t < start + count; t += 3)
            {
                TubeVertex a = vertices[indices[t]], b = vertices[indices[t + 1]], c = vertices[indices[t + 2]];
                Winding(a, b, c, out double nx, out double ny, out double nz);
                double length = Math.Sqrt(nx * nx + ny * ny + nz * nz);
                smallestArea = Math.Min(smallestArea, 0.5 * length);
                if (length > 0.0)
                {
                    double mx = a.NX + b.NX + c.NX, my = a.NY + b.NY + c.NY, mz = a.NZ + b.NZ + c.NZ;
                    double m = Math.Sqrt(mx * mx + my * my + mz * mz);
                    if (m > 0.0) worstAlignment = Math.Min(worstAlignment, (nx * mx + ny * my + nz * mz) / (length * m));
                }
            }
        }

        /// <summary>
        /// Triangles of indices[start, start + count) wound against their own vertex normals (inverted: the winding normal
        /// Cross(b − a, c − a) has a negative dot product with the sum of the three vertex normals; a GPU culls them where
        /// they should show and lights them from behind), and their summed area (m²). Zero-area triangles are never inverted.
        /// </summary>
        public static int Inverted(TubeVertex[] vertices, int[] indices, int start, int count, out double area)
        {
            int inverted = 0;
            area = 0.0;
            for (int t = start; t < start + count; t += 3)
            {
                TubeVertex a = vertices[indices[t]], b = vertices[indices[t + 1]], c = vertices[indices[t + 2]];
                Winding(a, b, c, out double nx, out double ny, out double nz);
                double along = nx * ((double)a.NX + b.NX + c.NX) + ny * ((double)a.NY + b.NY + c.NY) + nz * ((double)a.NZ + b.NZ + c.NZ);
                if (!(along < 0.0)) continue;
                inverted++;
                area += 0.5 * Math.Sqrt(nx * nx + ny * ny + nz * nz);
            }
            return inverted;
        }

        /// <summary>
        /// Smallest cosine between a vertex normal and the unit winding normal of a triangle of indices[start, start + count)
        /// that uses it, over triangles of area above <paramref name="minimumArea"/> (m²): 1 for a flat-shaded mesh, &gt; 0
        /// when no vertex is lit from behind on any triangle around it.
        /// </summary>
        public static double LeastNormalCosine(TubeVertex[] vertices, int[] indices, int start, int count, double minimumArea)
        {
            double least = double.MaxValue;
            for (int t = start; t < start + count; t += 3)
            {
                TubeVertex a = vertices[indices[t]], b = vertices[indices[t + 1]], c = vertices[indices[t + 2]];
                Winding(a, b, c, out double nx, out double ny, out double nz);
                double length = Math.Sqrt(nx * nx + ny * ny + nz * nz);
                if (!(0.5 * length > minimumArea)) continue;
                nx /= length; ny /= length; nz /= length;
                least = Math.Min(least, nx * a.NX + ny * a.NY + nz * a.NZ);
                least = Math.Min(least, nx * b.NX + ny * b.NY + nz * b.NZ);
                least = Math.Min(least, nx * c.NX + ny * c.NY + nz * c.NZ);
            }
            return least;
        }

        /// <summary>
        /// Consecutive rings of one piece of the builder's last build whose circles cross each other's planes: ring k (centre
        /// c_k, drawn radius r_k, plane normal t_k) lies in front of ring k − 1's plane iff (c_k − c_{k−1})·t_{k−1} ≥ r_k sin θ
        /// (θ the angle between the tangents), and ring k − 1 behind ring k's iff (c_k − c_{k−1})·t_k ≥ r_{k−1} sin θ.
        /// <paramref name="leastClearance"/> is the smallest of the two slacks (m) over all pairs; <paramref name="tips"/> counts
        /// the rings drawn as fold tips.
        /// </summary>
        public static int RingCrossings(TubeMeshBuilder builder, bool[] broken, out double leastClearance, out int tips)
        {
            RingLayout layout = builder.Layout;
            int n = layout.SegmentCount, segment = 0, crossings = 0;
            leastClearance = double.MaxValue;
            tips = 0;
            ReadOnlySpan<bool> flags = broken ?? Array.Empty<bool>();
            while (RopePieces.Next(flags, n, ref segment, out int a, out int b))
            {
                int first = layout.FirstRing(a), last = layout.FirstRing(b);
                for (int k = first; k <= last; k++)
                {
                    builder.DrawnRing(k, out _, out _, out _, out bool tip);
                    if (tip) tips++;
                }
                for (int k = first + 1; k <= last; k++)
                {
                    builder.DrawnRing(k - 1, out var c0, out var t0, out float r0, out _);
                    builder.DrawnRing(k, out var c1, out var t1, out float r1, out _);
                    double sx = c1.X - c0.X, sy = c1.Y - c0.Y, sz = c1.Z - c0.Z;
                    double ax = (double)t0.Y * t1.Z - (double)t0.Z * t1.Y, ay = (double)t0.Z * t1.X - (double)t0.X * t1.Z, az = (double)t0.X * t1.Y - (double)t0.Y * t1.X;
                    double sine = Math.Sqrt(ax * ax + ay * ay + az * az);
                    double ahead = sx * t0.X + sy * t0.Y + sz * t0.Z - r1 * sine;
                    double behind = sx * t1.X + sy * t1.Y + sz * t1.Z - r0 * sine;
                    double clearance = Math.Min(ahead, behind);
                    leastClearance = Math.Min(leastClearance, clearance);
                    if (!(clearance > 0.0)) crossings++;
                }
            }
            return crossings;
        }

        /// <summary>True when every one of the 12 floats of <paramref name="a"/> and <paramref name="b"/> has the same bits.</summary>
        public static bool SameBits(in TubeVertex a, in TubeVertex b) =>
            Bits(a.PX) == Bits(b.PX) && Bits(a.PY) == Bits(b.PY) && Bits(a.PZ) == Bits(b.PZ)
            && Bits(a.NX) == Bits(b.NX) && Bits(a.NY) == Bits(b.NY) && Bits(a.NZ) == Bits(b.NZ)
            && Bits(a.TX) == Bits(b.TX) && Bits(a.TY) == Bits(b.TY) && Bits(a.TZ) == Bits(b.TZ) && Bits(a.TW) == Bits(b.TW)
            && Bits(a.U) == Bits(b.U) && Bits(a.V) == Bits(b.V);

        /// <summary>Vertices among the first <paramref name="count"/> of <paramref name="a"/> and <paramref name="b"/> whose bits differ (<see cref="SameBits"/>).</summary>
        public static int DifferingVertices(TubeVertex[] a, TubeVertex[] b, int count)
        {
            int differing = 0;
            for (int k = 0; k < count; k++) if (!SameBits(a[k], b[k])) differing++;
            return differing;
        }

        private static int Bits(float v) => BitConverter.SingleToInt32Bits(v);

        /// <summary>True when every float of the first <paramref name="count"/> vertices is finite and every normal and tangent is unit length within 1e-3.</summary>
        public static bool AllFiniteAndUnit(TubeVertex[] vertices, int count)
        {
            for (int i = 0; i < count; i++)
            {
                TubeVertex v = vertices[i];
                float[] all = { v.PX, v.PY, v.PZ, v.NX, v.NY, v.NZ, v.TX, v.TY, v.TZ, v.TW, v.U, v.V };
                foreach (float value in all) if (!float.IsFinite(value)) return false;
                if (Math.Abs(Math.Sqrt(v.NX * v.NX + v.NY * v.NY + v.NZ * v.NZ) - 1.0) > 1e-3) return false;
                if (Math.Abs(Math.Sqrt(v.TX * v.TX + v.TY * v.TY + v.TZ * v.TZ) - 1.0) > 1e-3) return false;
            }
            return true;
        }
    }
}
