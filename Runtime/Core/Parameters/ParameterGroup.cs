namespace HookeRope
{
    /// <summary>The settings group a <see cref="ParameterInfo"/> row belongs to (inspector section, lab object).</summary>
    public enum ParameterGroup
    {
        /// <summary>Stiffness, density, Poisson ratio, damping.</summary>
        Material,
        /// <summary>Rest length, radius, segment count.</summary>
        Geometry,
        /// <summary>Solver kind, substeps, iterations, tension model, gravity.</summary>
        Solver,
        /// <summary>Attachment compliance.</summary>
        Attachments,
        /// <summary>Rope–collider friction.</summary>
        Collisions,
        /// <summary>Poisson thinning and necking.</summary>
        Radius,
        /// <summary>The break decision.</summary>
        Fracture,
        /// <summary>The procedural tube mesh and its material.</summary>
        Mesh,
        /// <summary>Viscous and air drag, air density and wind.</summary>
        Drag,
    }
}
