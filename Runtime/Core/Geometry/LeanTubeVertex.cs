using System.Runtime.InteropServices;

namespace HookeRope.Geometry
{
    /// <summary>
    /// One interleaved mesh vertex without a tangent, 8 float32 (32 bytes) in the order Position (3), Normal (3),
    /// TexCoord0 (2): for materials without a normal map, which never read the tangent. A third less to write and upload
    /// than <see cref="TubeVertex"/>; every field holds the same bits as the <see cref="TubeVertex"/> field of the same
    /// name in a build of the same input. Uploads directly with Unity's Mesh.SetVertexBufferData.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct LeanTubeVertex
    {
        /// <summary>Position x in metres (in the frame of the input positions).</summary>
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
        /// <summary>Texture u (around the rope, 0 … 1; on strands across the strand).</summary>
        public float U;
        /// <summary>Texture v (rest arc length times <see cref="TubeMeshSettings.VPerMetre"/>; on strands 1 at the base, 0 at the tip).</summary>
        public float V;

        /// <summary>Size of one vertex in bytes (32).</summary>
        public const int SizeInBytes = 32;
    }
}
