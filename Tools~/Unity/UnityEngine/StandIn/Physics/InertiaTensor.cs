using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: a symmetric 3×3 inertia tensor (kg·m²) in a body's frame, with the few operations mass properties need.</summary>
    internal readonly struct InertiaTensor
    {
        internal readonly float Xx, Yy, Zz, Xy, Xz, Yz;

        internal InertiaTensor(float xx, float yy, float zz, float xy, float xz, float yz)
        {
            Xx = xx; Yy = yy; Zz = zz; Xy = xy; Xz = xz; Yz = yz;
        }

        /// <summary>The tensor PhysX gives a body without simulation shapes: (1, 1, 1).</summary>
        internal static InertiaTensor Unit => new InertiaTensor(1f, 1f, 1f, 0f, 0f, 0f);

        internal static InertiaTensor Zero => default;

        /// <summary>Principal moments <paramref name="moments"/> about the axes <paramref name="rotation"/> maps x, y, z to: Σ Iₖ·aₖ·aₖᵀ.</summary>
        internal static InertiaTensor FromPrincipal(Vector3 moments, Quaternion rotation)
        {
            Vector3 a = rotation * new Vector3(1f, 0f, 0f), b = rotation * new Vector3(0f, 1f, 0f), c = rotation * new Vector3(0f, 0f, 1f);
            return Outer(a, moments.x) + Outer(b, moments.y) + Outer(c, moments.z);
        }

        /// <summary>Moments <paramref name="axial"/> about the unit <paramref name="axis"/> and <paramref name="transverse"/> about every axis normal to it.</summary>
        internal static InertiaTensor Axisymmetric(Vector3 axis, float axial, float transverse) =>
            new InertiaTensor(transverse, transverse, transverse, 0f, 0f, 0f) + Outer(axis, axial - transverse);

        /// <summary>Parallel-axis term of a point mass <paramref name="mass"/> at offset <paramref name="d"/>: m·(|d|²·E − d·dᵀ).</summary>
        internal static InertiaTensor PointMass(float mass, Vector3 d) =>
            new InertiaTensor(mass * (d.y * d.y + d.z * d.z), mass * (d.x * d.x + d.z * d.z), mass * (d.x * d.x + d.y * d.y),
                -mass * d.x * d.y, -mass * d.x * d.z, -mass * d.y * d.z);

        static InertiaTensor Outer(Vector3 a, float s) =>
            new InertiaTensor(s * a.x * a.x, s * a.y * a.y, s * a.z * a.z, s * a.x * a.y, s * a.x * a.z, s * a.y * a.z);

        public static InertiaTensor operator +(InertiaTensor a, InertiaTensor b) =>
            new InertiaTensor(a.Xx + b.Xx, a.Yy + b.Yy, a.Zz + b.Zz, a.Xy + b.Xy, a.Xz + b.Xz, a.Yz + b.Yz);

        internal InertiaTensor Scaled(float s) => new InertiaTensor(s * Xx, s * Yy, s * Zz, s * Xy, s * Xz, s * Yz);

        internal Vector3 Multiply(Vector3 v) =>
            new Vector3(Xx * v.x + Xy * v.y + Xz * v.z, Xy * v.x + Yy * v.y + Yz * v.z, Xz * v.x + Yz * v.y + Zz * v.z);

        /// <summary>The inverse; a singular tensor (a body of zero extent) gives zero, PhysX's "infinite inertia".</summary>
        internal InertiaTensor Inverse()
        {
            double cxx = (double)Yy * Zz - (double)Yz * Yz;
            double cxy = (double)Xz * Yz - (double)Xy * Zz;
            double cxz = (double)Xy * Yz - (double)Xz * Yy;
            double det = Xx * cxx + Xy * cxy + Xz * cxz;
            double scale = System.Math.Abs(Xx) + System.Math.Abs(Yy) + System.Math.Abs(Zz);
            if (!(System.Math.Abs(det) > 1e-18 * scale * scale * scale)) return Zero;
            double cyy = (double)Xx * Zz - (double)Xz * Xz;
            double cyz = (double)Xy * Xz - (double)Xx * Yz;
            double czz = (double)Xx * Yy - (double)Xy * Xy;
            double inv = 1.0 / det;
            return new InertiaTensor((float)(cxx * inv), (float)(cyy * inv), (float)(czz * inv), (float)(cxy * inv), (float)(cxz * inv), (float)(cyz * inv));
        }
    }
}
