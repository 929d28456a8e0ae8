namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Material.</summary>
    public class Material : Object
    {
        /// <summary>Create a temporary Material from a Shader.</summary>
        public Material(Shader shader) => throw Shim.NotRun;

        /// <summary>Create a temporary Material by copying the shader and all properties from the source Material.</summary>
        public Material(Material source) => throw Shim.NotRun;

        /// <summary>The material's texture.</summary>
        public Texture mainTexture { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Render queue of this material.</summary>
        public int renderQueue { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Sets a named float value.</summary>
        public void SetFloat(string name, float value) => throw Shim.NotRun;

        /// <summary>Enables a local shader keyword for this material.</summary>
        public void EnableKeyword(string keyword) => throw Shim.NotRun;

        /// <summary>Checks if material's shader has a property of a given name.</summary>
        public bool HasProperty(string name) => throw Shim.NotRun;

        /// <summary>Sets a named texture.</summary>
        public void SetTexture(string name, Texture value) => throw Shim.NotRun;

        /// <summary>Sets a named color value.</summary>
        public void SetColor(string name, Color value) => throw Shim.NotRun;

        /// <summary>The main color of the Material.</summary>
        public Color color { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
