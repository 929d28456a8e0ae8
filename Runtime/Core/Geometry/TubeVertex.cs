using System.Runtime.InteropServices;

namespace HookeRope.Geometry
{
    /// <summary>
    /// One interleaved mesh vertex, 12 float32 (48 bytes) in the order Position (3), Normal (3), Tangent (4),
    /// TexCoord0 (2), so a <c>TubeVertex[]</c> uploads directly with Unity's Mesh.SetVertexBufferData.
    /// Positions are in metres relative to the rope's first particle.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct TubeVertex
    {
        /// <summary>Position x in metres (rope-local, relative to the first particle).</summary>
        public float PX;
        /// <summary>Position y in metres.</summary>
        public float PY;
        /// <summary>Position z in metres.</summary>
        public float PZ;
        /// <summary>Unit outward normal x.</summary>
        public float NX;
        /// <summary>Unit outward normal y.</summary>
        public float NY;
        /// <summary>Unit outward normal z.</summary>
        public float NZ;
        /// <summary>Unit tangent x (direction of increasing u).</summary>
        public float TX;
        /// <summary>Unit tangent y.</summary>
        public float TY;
        /// <summary>Unit tangent z.</summary>
        public float TZ;
        /// <summary>Bitangent sign (+1: cross(normal, tangent) points along increasing v).</summary>
        public float TW;
        /// <summary>Texture u (around the rope, 0 … 1; on strands across the strand).</summary>
        public float U;
        /// <summary>Texture v (rest arc length times <see cref="TubeMeshSettings.VPerMetre"/>; on strands 1 at the base, 0 at the tip).</summary>
        public float V;

        /// <summary>Size of one vertex in bytes (48).</summary>
        public const int SizeInBytes = 48;
    }
}
