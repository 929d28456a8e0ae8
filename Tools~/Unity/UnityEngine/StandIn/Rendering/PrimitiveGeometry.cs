using System;
using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: vertex positions, normals and triangles of the built-in primitives, with the dimensions of
    /// the Manual's "Primitive and placeholder objects" page: Cube 1 m, Sphere 1 m diameter, Capsule 2 m high and
    /// 1 m wide (hemispherical caps), Cylinder 2 m high and 1 m wide, Plane 10 × 10 m in XZ facing +Y, Quad 1 × 1 m
    /// in XY facing −Z. Triangles wind clockwise seen from the front (Unity's front faces): Cross(b − a, c − a)
    /// points along the outward normal. Tessellation is the stand-in's own: Cube 24 vertices / 12 triangles, Plane
    /// 121 / 200, Quad 4 / 2, Sphere 24 × 16, Capsule 24 × (8 + 8), Cylinder 20 sides (Unity's own vertex counts
    /// could not be sourced; do not assert them).
    /// </summary>
    internal sealed class PrimitiveGeometry
    {
        const int Segments = 24;

        /// <summary>Vertex positions (m).</summary>
        internal readonly List<Vector3> Positions = new List<Vector3>();

        /// <summary>Unit vertex normals.</summary>
        internal readonly List<Vector3> Normals = new List<Vector3>();

        /// <summary>Triangle list (three indices per triangle).</summary>
        internal readonly List<int> Triangles = new List<int>();

        /// <summary>The geometry of <paramref name="type"/>.</summary>
        internal static PrimitiveGeometry Of(PrimitiveType type)
        {
            var g = new PrimitiveGeometry();
            switch (type)
            {
                case PrimitiveType.Cube: g.AddCube(); break;
                case PrimitiveType.Sphere: g.AddLatheRows(SphereRows()); break;
                case PrimitiveType.Capsule: g.AddLatheRows(CapsuleRows()); break;
                case PrimitiveType.Cylinder: g.AddCylinder(); break;
                case PrimitiveType.Plane: g.AddGrid(10f, 10); break;
                case PrimitiveType.Quad: g.AddQuad(); break;
                default: throw StandInError.Unsupported("PrimitiveType " + type);
            }
            return g;
        }

        int Vertex(Vector3 position, Vector3 normal)
        {
            Positions.Add(position);
            Normals.Add(normal);
            return Positions.Count - 1;
        }

        /// <summary>Adds triangle (a, b, c), flipping it if needed so that it faces <paramref name="outward"/>.</summary>
        void Triangle(int a, int b, int c, Vector3 outward)
        {
            var n = Vector3.Cross(Positions[b] - Positions[a], Positions[c] - Positions[a]);
            if (Vector3.Dot(n, outward) < 0f) { int t = b; b = c; c = t; }
            Triangles.Add(a);
            Triangles.Add(b);
            Triangles.Add(c);
        }

        /// <summary>Quad a-b-c-d (in order around its edge) as two triangles facing <paramref name="outward"/>.</summary>
        void Quad(int a, int b, int c, int d, Vector3 outward)
        {
            Triangle(a, b, c, outward);
            Triangle(a, c, d, outward);
        }

        void AddCube()
        {
            var axes = new[] { Vector3.right, Vector3.left, Vector3.up, Vector3.down, Vector3.forward, Vector3.back };
            foreach (var n in axes)
            {
                // Two unit axes spanning the face.
                var u = Math.Abs(n.y) > 0.5f ? Vector3.right : Vector3.up;
                var v = Vector3.Cross(n, u);
                var centre = n * 0.5f;
                int a = Vertex(centre - u * 0.5f - v * 0.5f, n);
                int b = Vertex(centre + u * 0.5f - v * 0.5f, n);
                int c = Vertex(centre + u * 0.5f + v * 0.5f, n);
                int d = Vertex(centre - u * 0.5f + v * 0.5f, n);
                Quad(a, b, c, d, n);
            }
        }

        void AddQuad()
        {
            var n = Vector3.back;
            int a = Vertex(new Vector3(-0.5f, -0.5f, 0f), n);
            int b = Vertex(new Vector3(0.5f, -0.5f, 0f), n);
            int c = Vertex(new Vector3(0.5f, 0.5f, 0f), n);
            int d = Vertex(new Vector3(-0.5f, 0.5f, 0f), n);
            Quad(a, b, c, d, n);
        }

        void AddGrid(float size, int cells)
        {
            int first = Positions.Count;
            for (int z = 0; z <= cells; z++)
            for (int x = 0; x <= cells; x++)
                Vertex(new Vector3(size * x / cells - size * 0.5f, 0f, size * z / cells - size * 0.5f), Vector3.up);
            for (int z = 0; z < cells; z++)
            for (int x = 0; x < cells; x++)
            {
                int a = first + z * (cells + 1) + x;
                Quad(a, a + 1, a + cells + 2, a + cells + 1, Vector3.up);
            }
        }

        void AddCylinder()
        {
            const int sides = 20;
            int side = Positions.Count;
            for (int i = 0; i <= sides; i++)
            {
                double angle = 2 * Math.PI * i / sides;
                var n = new Vector3((float)Math.Cos(angle), 0f, (float)Math.Sin(angle));
                Vertex(new Vector3(n.x * 0.5f, -1f, n.z * 0.5f), n);
                Vertex(new Vector3(n.x * 0.5f, 1f, n.z * 0.5f), n);
            }
            for (int i = 0; i < sides; i++)
            {
                int a = side + 2 * i;
                var outward = Normals[a] + Normals[a + 2];
                Quad(a, a + 2, a + 3, a + 1, outward);
            }
            foreach (float y in new[] { -1f, 1f })
            {
                var n = new Vector3(0f, y, 0f);
                int centre = Vertex(new Vector3(0f, y, 0f), n);
                for (int i = 0; i < sides; i++)
                {
                    double angle = 2 * Math.PI * i / sides;
                    Vertex(new Vector3(0.5f * (float)Math.Cos(angle), y, 0.5f * (float)Math.Sin(angle)), n);
                }
                for (int i = 0; i < sides; i++) Triangle(centre, centre + 1 + i, centre + 1 + (i + 1) % sides, n);
            }
        }

        /// <summary>A surface of revolution about Y: rows of (radius, height, normal-elevation) from the bottom pole to the top pole.</summary>
        void AddLatheRows(List<(float Radius, float Y, double Elevation)> rows)
        {
            int first = Positions.Count;
            foreach (var row in rows)
            for (int i = 0; i <= Segments; i++)
            {
                double angle = 2 * Math.PI * i / Segments;
                float c = (float)Math.Cos(angle), s = (float)Math.Sin(angle);
                float ce = (float)Math.Cos(row.Elevation), se = (float)Math.Sin(row.Elevation);
                Vertex(new Vector3(row.Radius * c, row.Y, row.Radius * s), new Vector3(ce * c, se, ce * s));
            }
            for (int r = 0; r + 1 < rows.Count; r++)
            for (int i = 0; i < Segments; i++)
            {
                int a = first + r * (Segments + 1) + i, b = a + 1, c = b + Segments + 1, d = a + Segments + 1;
                var outward = Normals[a] + Normals[b] + Normals[c] + Normals[d];
                if (rows[r].Radius > 0f) Triangle(a, b, c, outward);
                if (rows[r + 1].Radius > 0f) Triangle(a, c, d, outward);
            }
        }

        static List<(float, float, double)> SphereRows()
        {
            const int rings = 16;
            var rows = new List<(float, float, double)>();
            for (int j = 0; j <= rings; j++)
            {
                double elevation = -Math.PI / 2 + Math.PI * j / rings;
                rows.Add((j == 0 || j == rings ? 0f : 0.5f * (float)Math.Cos(elevation), 0.5f * (float)Math.Sin(elevation), elevation));
            }
            return rows;
        }

        static List<(float, float, double)> CapsuleRows()
        {
            const int capRings = 8;
            var rows = new List<(float, float, double)>();
            for (int j = 0; j <= capRings; j++)
            {
                double elevation = -Math.PI / 2 + Math.PI / 2 * j / capRings;
                rows.Add((j == 0 ? 0f : 0.5f * (float)Math.Cos(elevation), -0.5f + 0.5f * (float)Math.Sin(elevation), elevation));
            }
            for (int j = 0; j <= capRings; j++)
            {
                double elevation = Math.PI / 2 * j / capRings;
                rows.Add((j == capRings ? 0f : 0.5f * (float)Math.Cos(elevation), 0.5f + 0.5f * (float)Math.Sin(elevation), elevation));
            }
            return rows;
        }
    }
}
