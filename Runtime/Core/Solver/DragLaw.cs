using System;

namespace HookeRope.Solver
{
    /// <summary>
    /// Closed forms of the drag of <see cref="RopeSettings"/> for a uniform rope (the inspector's preview, the lab's checks). With
    /// a drag −c·v per metre, every swing mode decays as exp(−c·t/(2μ)); a straight rope falling broadside stops accelerating
    /// where c·v + ½·ρ·C_d·2R·v² = μ·g.
    /// </summary>
    internal static class DragLaw
    {
        /// <summary>Decay rate (1/s) of a swing's amplitude under viscous drag c (N·s/m²) on a rope of μ kg/m: c/(2μ); 0 without it.</summary>
        public static double SwingDecayRate(double viscous, double linearDensity) => viscous / (2.0 * linearDensity);

        /// <summary>
        /// Terminal velocity (m/s) of a straight horizontal rope falling broadside under gravity g (m/s²): the root of
        /// c·v + ½·ρ·C_d·2R·v² = μ·g (viscous c N·s/m², drag coefficient C_d, air density ρ kg/m³, radius R m, μ kg/m); +∞ without drag.
        /// </summary>
        public static double BroadsideTerminalVelocity(double viscous, double dragCoefficient, double airDensity, double radius, double linearDensity, double gravity)
        {
            double quadratic = airDensity * dragCoefficient * radius, weight = linearDensity * gravity;
            if (quadratic > 0.0) return 2.0 * weight / (viscous + Math.Sqrt(viscous * viscous + 4.0 * quadratic * weight));
            return viscous > 0.0 ? weight / viscous : double.PositiveInfinity;
        }
    }
}
