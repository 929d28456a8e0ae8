using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// How many triangles of a mesh range are wound against their own vertex normals (inverted: the geometric normal
    /// Cross(b − a, c − a) points away from the mean of the three vertex normals), and their area. A GPU culls such a
    /// triangle where it should be seen (a hole) and draws it lit from behind where it should be hidden (a dark patch).
    /// </summary>
    public readonly struct WindingCensus
    {
        /// <summary>Triangles examined.</summary>
        public readonly int Triangles;
        /// <summary>Triangles wound against their vertex normals.</summary>
        public readonly int Inverted;
        /// <summary>Summed area of the inverted triangles (m², the mesh's units squared).</summary>
        public readonly double InvertedArea;
        /// <summary>Smallest cosine between a triangle's geometric normal and its mean vertex normal (1 when there is no triangle).</summary>
        public readonly double LeastCosine;

        /// <summary>A census.</summary>
        public WindingCensus(int triangles, int inverted, double invertedArea, double leastCosine)
        {
            Triangles = triangles;
            Inverted = inverted;
            InvertedArea = invertedArea;
            LeastCosine = leastCosine;
        }

        /// <summary>
        /// The census of the triangles in <paramref name="indices"/>[<paramref name="start"/>, <paramref name="start"/> +
        /// <paramref name="count"/>) (a multiple of 3) over <paramref name="vertices"/>. Triangles of zero area are counted
        /// but never inverted.
        /// </summary>
        public static WindingCensus Of(TubeVertex[] vertices, int[] indices, int start, int count)
        {
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (indices == null) throw new ArgumentNullException(nameof(indices));
            if (start < 0 || count < 0 || count % 3 != 0 || start + count > indices.Length)
                throw new ArgumentOutOfRangeException(nameof(count), count, "the range must be whole triangles inside indices");
            int inverted = 0;
            double area = 0.0, least = 1.0;
            for (int k = start; k < start + count; k += 3)
            {
                if (!IsInverted(vertices[indices[k]], vertices[indices[k + 1]], vertices[indices[k + 2]], out double twiceArea, out double cosine)) 
                {
                    if (twiceArea > 0.0) least = Math.Min(least, cosine);
                    continue;
                }
                inverted++;
                area += 0.5 * twiceArea;
                least = Math.Min(least, cosine);
            }
            return new WindingCensus(count / 3, inverted, area, least);
        }

        /// <summary>
        /// True when triangle (a, b, c) is wound against the mean of its vertex normals; <paramref name="twiceArea"/> is
        /// |Cross(b − a, c − a)| and <paramref name="cosine"/> the cosine between that and the mean normal (1 for zero area).
        /// </summary>
        public static bool IsInverted(TubeVertex a, TubeVertex b, TubeVertex c, out double twiceArea, out double cosine)
        {
            Float3 pa = Position(a), pb = Position(b), pc = Position(c);
            Float3 winding = Float3.Cross(pb - pa, pc - pa);
            var normal = new Float3(a.NX + b.NX + c.NX, a.NY + b.NY + c.NY, a.NZ + b.NZ + c.NZ);
            twiceArea = winding.Length;
            double normalLength = normal.Length;
            if (!(twiceArea > 0.0) || !(normalLength > 0.0))
            {
                cosine = 1.0;
                return false;
            }
            cosine = Float3.Dot(winding, normal) / (twiceArea * normalLength);
            return cosine < 0.0;
        }

        static Float3 Position(TubeVertex v) => new Float3(v.PX, v.PY, v.PZ);
    }
}
