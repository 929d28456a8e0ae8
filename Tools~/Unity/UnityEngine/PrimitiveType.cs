namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.PrimitiveType: the various primitives that can be created using GameObject.CreatePrimitive.</summary>
    public enum PrimitiveType
    {
        /// <summary>A sphere primitive.</summary>
        Sphere = 0,
        /// <summary>A capsule primitive.</summary>
        Capsule = 1,
        /// <summary>A cylinder primitive.</summary>
        Cylinder = 2,
        /// <summary>A cube primitive.</summary>
        Cube = 3,
        /// <summary>A plane primitive.</summary>
        Plane = 4,
        /// <summary>A quad primitive.</summary>
        Quad = 5,
    }
}
