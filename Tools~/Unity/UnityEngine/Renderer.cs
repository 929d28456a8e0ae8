namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Renderer.</summary>
    public class Renderer : Component
    {
        /// <summary>Makes the rendered 3D object visible if enabled.</summary>
        public bool enabled { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The shared material of this object.</summary>
        public Material sharedMaterial { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>All the shared materials of this object.</summary>
        public Material[] sharedMaterials { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
