using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: Unity's built-in resources as asset files reference them. guid
    /// 0000000000000000e000000000000000 holds the primitive meshes (fileID 10202 Cube, 10206 Cylinder, 10207 Sphere,
    /// 10208 Capsule, 10209 Plane, 10210 Quad); guid 0000000000000000f000000000000000 the built-in extras, of which
    /// the stand-in knows Default-Material (10303). They map to the rendering stand-in's primitive meshes and default
    /// material; any other built-in resource is unknown (null here, so the loader reports it).
    /// </summary>
    internal static class BuiltinAssets
    {
        internal const string MeshesGuid = "0000000000000000e000000000000000";
        internal const string ExtrasGuid = "0000000000000000f000000000000000";

        /// <summary>The built-in resource <paramref name="fileId"/> of <paramref name="guid"/>, or null when the stand-in has none.</summary>
        internal static Object Find(string guid, long fileId)
        {
            if (guid == MeshesGuid)
            {
                switch (fileId)
                {
                    case 10202: return PrimitiveMeshes.Get(PrimitiveType.Cube);
                    case 10206: return PrimitiveMeshes.Get(PrimitiveType.Cylinder);
                    case 10207: return PrimitiveMeshes.Get(PrimitiveType.Sphere);
                    case 10208: return PrimitiveMeshes.Get(PrimitiveType.Capsule);
                    case 10209: return PrimitiveMeshes.Get(PrimitiveType.Plane);
                    case 10210: return PrimitiveMeshes.Get(PrimitiveType.Quad);
                }
            }
            if (guid == ExtrasGuid && fileId == 10303) return BuiltinMaterials.Default;
            return null;
        }
    }
}
