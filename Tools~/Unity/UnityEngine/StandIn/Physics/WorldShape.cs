using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>The kinds of <see cref="WorldShape"/>.</summary>
    internal enum ShapeKind
    {
        /// <summary>No geometry (a MeshCollider without a mesh): collides with nothing.</summary>
        None,
        /// <summary>A capsule: the points within Radius of the segment A–B (a sphere when A = B).</summary>
        Capsule,
        /// <summary>An oriented box: Center, Rotation and half extents Half (one of them may be 0: a flat rectangle).</summary>
        Box,
        /// <summary>Geometry the stand-in cannot test (reported by name when a test needs it).</summary>
        Unsupported,
    }

    /// <summary>Not part of Unity: a collider's geometry in world space, as the physics engine sees it.</summary>
    internal readonly struct WorldShape
    {
        internal readonly ShapeKind Kind;
        internal readonly Vector3 A, B;
        internal readonly float Radius;
        internal readonly Vector3 Center;
        internal readonly Quaternion Rotation;
        internal readonly Vector3 Half;
        internal readonly Vector3 AxisX, AxisY, AxisZ;
        /// <summary>For <see cref="ShapeKind.Unsupported"/>: the collider, which describes what the stand-in cannot do.</summary>
        internal readonly Collider Source;

        WorldShape(ShapeKind kind, Vector3 a, Vector3 b, float radius, Vector3 center, Quaternion rotation, Vector3 half, Collider source)
        {
            Kind = kind;
            A = a;
            B = b;
            Radius = radius;
            Center = center;
            Rotation = rotation;
            Half = half;
            AxisX = rotation * new Vector3(1f, 0f, 0f);
            AxisY = rotation * new Vector3(0f, 1f, 0f);
            AxisZ = rotation * new Vector3(0f, 0f, 1f);
            Source = source;
        }

        internal static WorldShape Nothing => new WorldShape(ShapeKind.None, default, default, 0f, default, Quaternion.identity, default, null);

        internal static WorldShape NotSupported(Collider source) => new WorldShape(ShapeKind.Unsupported, default, default, 0f, default, Quaternion.identity, default, source);

        /// <summary>What the stand-in cannot test, for the NotSupportedException (built only when thrown).</summary>
        internal string Unsupported => Source is null ? "unknown geometry" : Source.UnsupportedGeometry();

        internal static WorldShape Sphere(Vector3 center, float radius) =>
            new WorldShape(ShapeKind.Capsule, center, center, radius, center, Quaternion.identity, default, null);

        /// <summary>A capsule around <paramref name="center"/> along the unit <paramref name="axis"/>, its segment ±<paramref name="halfSegment"/>.</summary>
        internal static WorldShape Capsule(Vector3 center, Vector3 axis, float halfSegment, float radius) =>
            new WorldShape(ShapeKind.Capsule, center - axis * halfSegment, center + axis * halfSegment, radius, center, Quaternion.identity, default, null);

        internal static WorldShape Box(Vector3 center, Quaternion rotation, Vector3 half) =>
            new WorldShape(ShapeKind.Box, center, center, 0f, center, rotation, half, null);

        /// <summary>Half extents of the world axis-aligned box around the shape.</summary>
        internal Vector3 AabbHalf()
        {
            switch (Kind)
            {
                case ShapeKind.Capsule:
                {
                    var d = (B - A) * 0.5f;
                    return new Vector3(System.Math.Abs(d.x) + Radius, System.Math.Abs(d.y) + Radius, System.Math.Abs(d.z) + Radius);
                }
                case ShapeKind.Box:
                    return new Vector3(
                        System.Math.Abs(AxisX.x) * Half.x + System.Math.Abs(AxisY.x) * Half.y + System.Math.Abs(AxisZ.x) * Half.z,
                        System.Math.Abs(AxisX.y) * Half.x + System.Math.Abs(AxisY.y) * Half.y + System.Math.Abs(AxisZ.y) * Half.z,
                        System.Math.Abs(AxisX.z) * Half.x + System.Math.Abs(AxisY.z) * Half.y + System.Math.Abs(AxisZ.z) * Half.z);
                default:
                    return Vector3.zero;
            }
        }
    }
}
