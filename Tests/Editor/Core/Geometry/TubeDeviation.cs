using System;
using HookeRope.Geometry;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// How far a built tube is from the smooth tube it samples, in double precision: the smooth tube has the uniform
    /// Catmull–Rom curve through the particles as its centre (ends mirrored, as the builder's), a constant radius r, and
    /// circular cross-sections normal to the curve. Measured both ways on an intact piece (caps excluded): from points of the
    /// smooth tube (stations × angles per segment) to the nearest drawn triangle, and from points of the drawn triangles
    /// (vertices, edge midpoints, centroids) to the smooth surface.
    /// </summary>
    internal static class TubeDeviation
    {
        /// <summary>Largest distance (m) between the smooth tube of <paramref name="shape"/> (radius <paramref name="r"/>) and the drawn triangles, both ways.</summary>
        public static double Largest(RopeShape shape, float r, RingLayout layout, int radial, TubeVertex[] vertices,
            out double idealToMesh, out double meshToIdeal)
        {
            int n = shape.Segments;
            int stride = radial + 1;
            const int dense = 64;
            // dense samples of the smooth centre line
            var cx = new double[n * dense + 1];
            var cy = new double[n * dense + 1];
            var cz = new double[n * dense + 1];
            for (int j = 0; j < n; j++)
                for (int q = 0; q < dense; q++)
                    Centre(shape, j, (double)q / dense, out cx[j * dense + q], out cy[j * dense + q], out cz[j * dense + q]);
            Centre(shape, n - 1, 1.0, out cx[n * dense], out cy[n * dense], out cz[n * dense]);

            // ring index range of each segment, to look up nearby triangles
            ReadOnlySpan<int> segments = layout.RingSegments;
            int rings = layout.RingCount;
            int capVertices = radial + 1; // the start cap comes first
            idealToMesh = 0.0;
            const int stations = 8, angles = 24;
            for (int j = 0; j < n; j++)
            {
                int firstRing = layout.FirstRing(Math.Max(0, j - 1));
                int lastRing = Math.Min(rings - 1, layout.FirstRing(Math.Min(n, j + 2)));
                for (int q = 0; q < stations; q++)
                {
                    double t = (q + 0.5) / stations;
                    Centre(shape, j, t, out double px, out double py, out double pz);
                    Tangent(shape, j, t, out double tx, out double ty, out double tz);
                    Basis(tx, ty, tz, out double ux, out double uy, out double uz, out double vx, out double vy, out double vz);
                    for (int a = 0; a < angles; a++)
                    {
                        double phi = 2.0 * Math.PI * (a + 0.37) / angles;
                        double qx = px + r * (Math.Cos(phi) * ux + Math.Sin(phi) * vx);
                        double qy = py + r * (Math.Cos(phi) * uy + Math.Sin(phi) * vy);
                        double qz = pz + r * (Math.Cos(phi) * uz + Math.Sin(phi) * vz);
                        double best = double.MaxValue;
                        for (int k = firstRing; k < lastRing; k++)
                        {
                            int b0 = capVertices + k * stride, b1 = b0 + stride;
                            for (int i = 0; i < radial; i++)
                            {
                                best = Math.Min(best, PointTriangle(qx, qy, qz, vertices[b0 + i], vertices[b0 + i + 1], vertices[b1 + i]));
                                best = Math.Min(best, PointTriangle(qx, qy, qz, vertices[b0 + i + 1], vertices[b1 + i + 1], vertices[b1 + i]));
                            }
                        }
                        idealToMesh = Math.Max(idealToMesh, best);
                    }
                }
            }

            // the other way: points of every tube triangle (corners, edge midpoints, centroid) to the smooth surface
            meshToIdeal = 0.0;
            for (int k = 0; k + 1 < rings; k++)
            {
                int j = segments[k];
                int from = Math.Max(0, (j - 1) * dense), to = Math.Min(n * dense, (j + 3) * dense);
                int b0 = capVertices + k * stride, b1 = b0 + stride;
                for (int i = 0; i < radial; i++)
                {
                    for (int half = 0; half < 2; half++)
                    {
                        TubeVertex A = half == 0 ? vertices[b0 + i] : vertices[b0 + i + 1];
                        TubeVertex B = half == 0 ? vertices[b0 + i + 1] : vertices[b1 + i + 1];
                        TubeVertex C = vertices[b1 + i];
                        for (int q = 0; q < 7; q++)
                        {
                            double wa = q == 0 ? 1 : q == 3 || q == 5 ? 0.5 : q == 6 ? 1.0 / 3 : 0;
                            double wb = q == 1 ? 1 : q == 3 || q == 4 ? 0.5 : q == 6 ? 1.0 / 3 : 0;
                            double wc = 1.0 - wa - wb;
                            double x = wa * A.PX + wb * B.PX + wc * C.PX, y = wa * A.PY + wb * B.PY + wc * C.PY, z = wa * A.PZ + wb * B.PZ + wc * C.PZ;
                            meshToIdeal = Math.Max(meshToIdeal, Math.Abs(DistanceToPolyline(x, y, z, cx, cy, cz, from, to) - r));
                        }
                    }
                }
            }
            return Math.Max(idealToMesh, meshToIdeal);
        }

        /// <summary>The uniform Catmull–Rom centre at fraction t of segment j (ends mirrored).</summary>
        public static void Centre(RopeShape s, int j, double t, out double x, out double y, out double z)
        {
            int n = s.Segments;
            double t2 = t * t, t3 = t2 * t;
            double w0 = 0.5 * (-t + 2 * t2 - t3), w1 = 0.5 * (2 - 5 * t2 + 3 * t3), w2 = 0.5 * (t + 4 * t2 - 3 * t3), w3 = 0.5 * (-t2 + t3);
            x = Blend(s.X, j, n, w0, w1, w2, w3);
            y = Blend(s.Y, j, n, w0, w1, w2, w3);
            z = Blend(s.Z, j, n, w0, w1, w2, w3);
        }

        private static void Tangent(RopeShape s, int j, double t, out double x, out double y, out double z)
        {
            const double h = 1e-5;
            double t0 = Math.Max(0.0, t - h), t1 = Math.Min(1.0, t + h);
            Centre(s, j, t0, out double ax, out double ay, out double az);
            Centre(s, j, t1, out double bx, out double by, out double bz);
            x = bx - ax; y = by - ay; z = bz - az;
            double l = Math.Sqrt(x * x + y * y + z * z);
            x /= l; y /= l; z /= l;
        }

        private static double Blend(float[] p, int j, int n, double w0, double w1, double w2, double w3)
        {
            double p1 = p[j], p2 = p[j + 1];
            double p0 = j > 0 ? p[j - 1] : 2 * p1 - p2;
            double p3 = j + 2 <= n ? p[j + 2] : 2 * p2 - p1;
            return p0 * w0 + p1 * w1 + p2 * w2 + p3 * w3;
        }

        private static void Basis(double tx, double ty, double tz, out double ux, out double uy, out double uz, out double vx, out double vy, out double vz)
        {
            double ax = Math.Abs(tx) < 0.9 ? 1 : 0, ay = Math.Abs(tx) < 0.9 ? 0 : 1, az = 0;
            ux = ay * tz - az * ty; uy = az * tx - ax * tz; uz = ax * ty - ay * tx;
            double l = Math.Sqrt(ux * ux + uy * uy + uz * uz);
            ux /= l; uy /= l; uz /= l;
            vx = ty * uz - tz * uy; vy = tz * ux - tx * uz; vz = tx * uy - ty * ux;
        }

        private static double DistanceToPolyline(double x, double y, double z, double[] cx, double[] cy, double[] cz, int from, int to)
        {
            double best = double.MaxValue;
            for (int i = from; i < to; i++)
            {
                double dx = cx[i + 1] - cx[i], dy = cy[i + 1] - cy[i], dz = cz[i + 1] - cz[i];
                double l2 = dx * dx + dy * dy + dz * dz;
                double u = l2 > 0 ? ((x - cx[i]) * dx + (y - cy[i]) * dy + (z - cz[i]) * dz) / l2 : 0;
                u = Math.Max(0, Math.Min(1, u));
                double ex = x - (cx[i] + u * dx), ey = y - (cy[i] + u * dy), ez = z - (cz[i] + u * dz);
                best = Math.Min(best, ex * ex + ey * ey + ez * ez);
            }
            return Math.Sqrt(best);
        }

        /// <summary>Distance from a point to a triangle (closest point by regions, Ericson's "Real-Time Collision Detection", §5.1.5).</summary>
        private static double PointTriangle(double px, double py, double pz, TubeVertex A, TubeVertex B, TubeVertex C)
        {
            double ax = A.PX, ay = A.PY, az = A.PZ;
            double abx = B.PX - ax, aby = B.PY - ay, abz = B.PZ - az;
            double acx = C.PX - ax, acy = C.PY - ay, acz = C.PZ - az;
            double apx = px - ax, apy = py - ay, apz = pz - az;
            double d1 = abx * apx + aby * apy + abz * apz, d2 = acx * apx + acy * apy + acz * apz;
            double qx, qy, qz;
            if (d1 <= 0 && d2 <= 0) { qx = ax; qy = ay; qz = az; return Length(px - qx, py - qy, pz - qz); }
            double bpx = px - B.PX, bpy = py - B.PY, bpz = pz - B.PZ;
            double d3 = abx * bpx + aby * bpy + abz * bpz, d4 = acx * bpx + acy * bpy + acz * bpz;
            if (d3 >= 0 && d4 <= d3) return Length(px - B.PX, py - B.PY, pz - B.PZ);
            double vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0)
            {
                double v = d1 / (d1 - d3);
                return Length(px - (ax + v * abx), py - (ay + v * aby), pz - (az + v * abz));
            }
            double cpx = px - C.PX, cpy = py - C.PY, cpz = pz - C.PZ;
            double d5 = abx * cpx + aby * cpy + abz * cpz, d6 = acx * cpx + acy * cpy + acz * cpz;
            if (d6 >= 0 && d5 <= d6) return Length(px - C.PX, py - C.PY, pz - C.PZ);
            double vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0)
            {
                double w = d2 / (d2 - d6);
                return Length(px - (ax + w * acx), py - (ay + w * acy), pz - (az + w * acz));
            }
            double va = d3 * d6 - d5 * d4;
            if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
            {
                double w = (d4 - d3) / (d4 - d3 + (d5 - d6));
                return Length(px - (B.PX + w * (C.PX - B.PX)), py - (B.PY + w * (C.PY - B.PY)), pz - (B.PZ + w * (C.PZ - B.PZ)));
            }
            double denom = 1.0 / (va + vb + vc);
            double vv = vb * denom, ww = vc * denom;
            return Length(px - (ax + abx * vv + acx * ww), py - (ay + aby * vv + acy * ww), pz - (az + abz * vv + acz * ww));
        }

        private static double Length(double x, double y, double z) => Math.Sqrt(x * x + y * y + z * z);
    }
}
