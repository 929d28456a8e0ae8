using HookeRope.StandIn;

namespace UnityEngine
{
    public sealed partial class GameObject
    {
        /// <summary>
        /// Creates a game object with a primitive mesh renderer and appropriate collider: MeshFilter (Unity's built-in
        /// mesh), MeshRenderer (Default-Material) and a SphereCollider (Sphere, radius 0.5), CapsuleCollider
        /// (Capsule and Cylinder, radius 0.5, height 2), BoxCollider (Cube, size 1) or MeshCollider (Plane, Quad).
        /// </summary>
        public static GameObject CreatePrimitive(PrimitiveType type)
        {
            var go = new GameObject(type.ToString());
            go.AddComponent<MeshFilter>().sharedMesh = PrimitiveMeshes.Get(type);
            go.AddComponent<MeshRenderer>().sharedMaterial = BuiltinMaterials.Default;
            switch (type)
            {
                case PrimitiveType.Sphere:
                    go.AddComponent<SphereCollider>().radius = 0.5f;
                    break;
                case PrimitiveType.Capsule:
                case PrimitiveType.Cylinder:
                {
                    var capsule = go.AddComponent<CapsuleCollider>();
                    capsule.radius = 0.5f;
                    capsule.height = 2f;
                    capsule.direction = 1;
                    break;
                }
                case PrimitiveType.Cube:
                    go.AddComponent<BoxCollider>().size = Vector3.one;
                    break;
                default:
                    go.AddComponent<MeshCollider>(); // like Unity, the collider takes its shape from the MeshFilter
                    break;
            }
            return go;
        }
    }
}
