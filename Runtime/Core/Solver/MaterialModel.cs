namespace HookeRope.Solver
{
    /// <summary>The constitutive law of the rope's segments (issue 15).</summary>
    public enum MaterialModel
    {
        /// <summary>Linear elastic (Hooke): the force follows the stretch, E·A·(l/L − 1), to any strain.</summary>
        Elastic = 0,

        /// <summary>
        /// Elastic up to the yield strain, then plastic with a hardening modulus (0 = a plateau) and a permanent set that
        /// stays when unloaded; at the necking strain the defect segment necks and softens until the ultimate strain,
        /// where its force is zero and the rope breaks.
        /// </summary>
        ElasticPlastic = 1,
    }
}
