using System;
using System.Collections.Generic;
using HookeRope.Geometry;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// The triangles of one documentation figure (world metres, Y up): the rope's tube mesh exactly as the core builds
    /// it (<see cref="RopeSimulation.FillMesh(TubeVertex[], int[])"/>, burr strands included), plus boxes, a torus and a
    /// cylinder for the rigs.
    /// </summary>
    public sealed class FigureScene
    {
        /// <summary>Largest edge (m) of the cells box faces are split into (keeps the light and depth well sampled).</summary>
        public const float BoxCell = 0.25f;

        readonly List<SceneTriangle> triangles = new List<SceneTriangle>();

        /// <summary>Every triangle added so far.</summary>
        public IReadOnlyList<SceneTriangle> Triangles => triangles;

        /// <summary>Number of rope triangles (the core's tube and cap triangles).</summary>
        public int RopeTriangleCount { get; private set; }

        /// <summary>Adds one triangle.</summary>
        public void Add(SceneTriangle triangle)
        {
            triangles.Add(triangle);
            if (triangle.Kind == SurfaceKind.Rope) RopeTriangleCount++;
        }

        /// <summary>Number of burr-strand triangles (the core's second submesh).</summary>
        public int BurrTriangleCount { get; private set; }

        /// <summary>
        /// Adds the rope's current mesh from the core (vertices in the rope-local frame, moved by the rope's origin and by
        /// <paramref name="offset"/> m): the tube and caps in <paramref name="color"/>, and the burr strands of broken ends
        /// (when any) in the same colour tinted by <paramref name="burrTexture"/> at the core's uvs (the package's burr
        /// material: a copy of the tube material with the burr texture; null draws the strands untextured). Each
        /// triangle's normal is the mean of its three vertex normals. Returns what the core wrote.
        /// </summary>
        public TubeMeshUpdate AddRope(RopeSimulation simulation, uint color, Float3 offset = default, FigureTexture burrTexture = null) =>
            AddRope(simulation, color, offset, burrTexture, Float3.Zero, color);

        /// <summary>
        /// <see cref="AddRope(RopeSimulation, uint, Float3, FigureTexture)"/> as a GPU with back-face culling draws it for a
        /// camera on the side of <paramref name="towardCamera"/> (unit): a triangle whose winding (Cross(b − a, c − a), the
        /// core's front face) faces away from the camera is left out, and tube triangles wound against their own vertex
        /// normals (<see cref="WindingCensus.IsInverted"/>) are drawn in <paramref name="invertedColor"/>, lit from their
        /// vertex normals as a GPU lights them.
        /// </summary>
        public TubeMeshUpdate AddRopeCulled(RopeSimulation simulation, uint color, Float3 towardCamera, uint invertedColor, Float3 offset = default,
            FigureTexture burrTexture = null) =>
            AddRope(simulation, color, offset, burrTexture, towardCamera, invertedColor);

        TubeMeshUpdate AddRope(RopeSimulation simulation, uint color, Float3 offset, FigureTexture burrTexture, Float3 cullToward, uint invertedColor)
        {
            var vertices = new TubeVertex[simulation.GetVertexCount()];
            var indices = new int[simulation.GetIndexCount()];
            var update = simulation.FillMesh(vertices, indices);
            var origin = simulation.Rope.Origin + offset;
            bool cull = cullToward.LengthSquared > 0f;
            for (int i = 0; i + 2 < update.IndexCount; i += 3)
            {
                var a = vertices[indices[i]];
                var b = vertices[indices[i + 1]];
                var c = vertices[indices[i + 2]];
                var normal = new Float3(a.NX + b.NX + c.NX, a.NY + b.NY + c.NY, a.NZ + b.NZ + c.NZ);
                if (cull && Float3.Dot(Float3.Cross(Position(b) - Position(a), Position(c) - Position(a)), cullToward) <= 0f) continue;
                if (i < update.TubeIndexCount)
                    Add(new SceneTriangle(Position(a) + origin, Position(b) + origin, Position(c) + origin, normal,
                        cull && WindingCensus.IsInverted(a, b, c, out _, out _) ? invertedColor : color, SurfaceKind.Rope));
                else
                {
                    Add(new SceneTriangle(Position(a) + origin, Position(b) + origin, Position(c) + origin, normal, color, SurfaceKind.Burr,
                        burrTexture, a.U, a.V, b.U, b.V, c.U, c.V));
                    BurrTriangleCount++;
                }
            }
            return update;
        }

        /// <summary>
        /// Adds a closed cylinder (a bar) around the segment <paramref name="from"/> → <paramref name="to"/> (m) of
        /// <paramref name="radius"/> m with <paramref name="sides"/> flat sides and two caps.
        /// </summary>
        public void AddCylinder(Float3 from, Float3 to, float radius, uint color, int sides = 96)
        {
            var axis = (to - from).NormalizedOr(new Float3(0f, 0f, 1f));
            var u = FrameAxis(axis);
            var v = Float3.Cross(axis, u);
            Float3 Around(int i)
            {
                double a = 2 * Math.PI * i / sides;
                return u * (float)Math.Cos(a) + v * (float)Math.Sin(a);
            }
            for (int i = 0; i < sides; i++)
            {
                var d0 = Around(i);
                var d1 = Around(i + 1);
                var normal = d0 + d1;
                Add(new SceneTriangle(from + d0 * radius, from + d1 * radius, to + d1 * radius, normal, color, SurfaceKind.Prop));
                Add(new SceneTriangle(from + d0 * radius, to + d1 * radius, to + d0 * radius, normal, color, SurfaceKind.Prop));
                Add(new SceneTriangle(from, from + d1 * radius, from + d0 * radius, -axis, color, SurfaceKind.Prop));
                Add(new SceneTriangle(to, to + d0 * radius, to + d1 * radius, axis, color, SurfaceKind.Prop));
            }
        }

        /// <summary>A unit vector perpendicular to <paramref name="axis"/>.</summary>
        static Float3 FrameAxis(Float3 axis)
        {
            var helper = Math.Abs(axis.Y) < 0.9f ? new Float3(0f, 1f, 0f) : new Float3(1f, 0f, 0f);
            return Float3.Cross(helper, axis).NormalizedOr(new Float3(1f, 0f, 0f));
        }

        static Float3 Position(TubeVertex v) => new Float3(v.PX, v.PY, v.PZ);

        /// <summary>Adds an axis-aligned box (centre and half extents in m), its faces split into cells of at most <see cref="BoxCell"/>.</summary>
        public void AddBox(Float3 center, Float3 halfExtents, uint color)
        {
            var x = new Float3(halfExtents.X, 0f, 0f);
            var y = new Float3(0f, halfExtents.Y, 0f);
            var z = new Float3(0f, 0f, halfExtents.Z);
            Face(center + x, y, z, color);
            Face(center - x, z, y, color);
            Face(center + y, z, x, color);
            Face(center - y, x, z, color);
            Face(center + z, x, y, color);
            Face(center - z, y, x, color);
        }

        /// <summary>One box face: centre, two half-edge vectors whose cross product is the outward normal.</summary>
        void Face(Float3 center, Float3 u, Float3 v, uint color)
        {
            var normal = Float3.Cross(u, v);
            int nu = Math.Max(1, (int)Math.Ceiling(2 * u.Length / BoxCell));
            int nv = Math.Max(1, (int)Math.Ceiling(2 * v.Length / BoxCell));
            var corner = center - u - v;
            var du = u * (2f / nu);
            var dv = v * (2f / nv);
            for (int i = 0; i < nu; i++)
            {
                for (int j = 0; j < nv; j++)
                {
                    var p = corner + du * i + dv * j;
                    Add(new SceneTriangle(p, p + du, p + du + dv, normal, color, SurfaceKind.Prop));
                    Add(new SceneTriangle(p, p + du + dv, p + dv, normal, color, SurfaceKind.Prop));
                }
            }
        }

        /// <summary>
        /// Adds a torus (a D-ring, a shackle) around <paramref name="center"/> whose ring lies in the plane spanned by
        /// <paramref name="axisU"/> and <paramref name="axisV"/> (unit, orthogonal); radii in m.
        /// </summary>
        public void AddTorus(Float3 center, Float3 axisU, Float3 axisV, float majorRadius, float minorRadius, uint color, int around = 24, int tube = 8)
        {
            var axisW = Float3.Cross(axisU, axisV);
            Float3 Point(int i, int j, out Float3 normal)
            {
                double a = 2 * Math.PI * i / around, b = 2 * Math.PI * j / tube;
                var radial = axisU * (float)Math.Cos(a) + axisV * (float)Math.Sin(a);
                normal = radial * (float)Math.Cos(b) + axisW * (float)Math.Sin(b);
                return center + radial * majorRadius + normal * minorRadius;
            }
            for (int i = 0; i < around; i++)
            {
                for (int j = 0; j < tube; j++)
                {
                    var p00 = Point(i, j, out var n00);
                    var p10 = Point(i + 1, j, out var n10);
                    var p11 = Point(i + 1, j + 1, out var n11);
                    var p01 = Point(i, j + 1, out var n01);
                    Add(new SceneTriangle(p00, p10, p11, n00 + n10 + n11, color, SurfaceKind.Prop));
                    Add(new SceneTriangle(p00, p11, p01, n00 + n11 + n01, color, SurfaceKind.Prop));
                }
            }
        }
    }
}
