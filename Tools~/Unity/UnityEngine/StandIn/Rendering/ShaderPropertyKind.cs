namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the ShaderLab property types of the stand-in's shader tables (Float, Range and Int store floats; Color and Vector store colours).</summary>
    internal enum ShaderPropertyKind
    {
        /// <summary>Float property.</summary>
        Float,
        /// <summary>Range(min, max) property (a float).</summary>
        Range,
        /// <summary>Int property (stored as a float, as Material.SetInt does).</summary>
        Int,
        /// <summary>Color property.</summary>
        Color,
        /// <summary>Vector property (stored as a colour, as Material.SetVector does).</summary>
        Vector,
        /// <summary>2D, 3D, Cube or 2DArray texture property.</summary>
        Texture,
    }
}
