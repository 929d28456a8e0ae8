using System;

namespace HookeRope.Solver
{
    /// <summary>
    /// The contacts of the exact chain solve (<see cref="ExactChainSolver"/>), Coulomb friction included. A contact of the set
    /// is free (the particle moves with its whole mobility w) or held on the surface, where friction is an implicit
    /// tangential damper: the substep's friction impulse is F = −ζ·s (N·s², ζ in kg) with s the particle's slip over the
    /// substep relative to the collider, so its tangential mobility is w_t = 1/(m + ζ) and W = w_t (I − c cᵀ) in the block
    /// system (symmetric, positive definite). A damper can only slow the slip, never reverse it, and does negative work,
    /// F·s = −ζ|s|²: whatever ζ a contact has, friction cannot add energy, and no contact position is prescribed that a
    /// stiff segment could not follow (which is what made sticking particles fixed in the solve throw loads up).
    /// <para>
    /// Each contact also prescribes a displacement u, folded into its two segments' residuals (R_{i−1} += u, R_i −= u: exact,
    /// R is linear in the positions), so the solve knows every displacement a contact makes and none moves a particle
    /// behind its back (which strained stiff segments without the solve seeing it: the energy gain of heavy loads swinging
    /// into a sphere). Held: onto the surface, −gap·c (a contact is only held with a gap once the chain drives it past it:
    /// one found with a gap starts free), or sticking back to where the substep started, and the friction's part of the
    /// slip, −w_t·(ζ·s₀ + G_t), s₀ the slip before this iteration and G_t the friction the substep has applied so far.
    /// Free: −w·G, the substep's contact impulse given back, so that a contact released after some iteration gives none.
    /// </para>
    /// <para>
    /// The contact impulse G = m·motion − pull (h² times the force, summed over the substep with the push-outs) is what the
    /// solve produced: N = G·c is its normal impulse (tension × wrap for a rope over a collider). Normal states and
    /// friction are decided by the active-set passes (<see cref="Update"/>) against that N. Sticking: ζ so large
    /// (<see cref="CreepSpeed"/>) that the friction reaches the cone μ_s·κ·N only when the particle creeps at 0.1 mm/s.
    /// Where the friction ζ|s| a solution asks exceeds the cone the contact slides, and a sliding contact's ζ is the one
    /// whose friction is the kinetic cone, ζ·cone/(ζ|s|), iterated through the passes (and kept from one substep to the
    /// next, where it is the first guess): Coulomb's bound μ_k·κ·N opposing the slip, still a damper. A sliding contact
    /// whose ζ reaches the sticking one sticks again.
    /// </para>
    /// <para>
    /// κ is the rope's discretisation: a contact particle stands for the piece of rope around it, which turns by the bend
    /// angle Δθ between its two segments. Coulomb at a point whose normal bisects that bend holds the tension ratio
    /// (1 + μ tan(Δθ/2))/(1 − μ tan(Δθ/2)); over the continuous piece it is e^{μΔθ} (Euler–Eytelwein). The bound κ·μ·N with
    /// κ = tanh(μΔθ/2)/(μ tan(Δθ/2)) gives each contact exactly e^{μΔθ}, so the whole wrap holds e^{μθ} for any segment
    /// length; κ → 1 as Δθ → 0 (a straight rope pressed on a surface has plain μ).
    /// </para>
    /// </summary>
    internal static class ChainContacts
    {
        /// <summary>Fastest creep (m/s) of a contact inside its friction cone: sticking is a damper that lets it slip this fast at the cone's edge.</summary>
        public const double CreepSpeed = 1e-4;

        /// <summary>A contact's friction impulse may differ from the one Coulomb asks for by this fraction of its cone before the passes solve again.</summary>
        public const double FrictionTolerance = 1e-3;

        /// <summary>
        /// A contact whose normal impulse is below this fraction of the largest one of the last substep
        /// (<see cref="ChainState.ContactNormalScale"/>) slides without friction (ζ = 0): its friction is negligible, and
        /// following it would only make the passes run out.
        /// </summary>
        public const double NegligibleNormal = 1e-3;

        /// <summary>
        /// A free contact is held once the solution drives it past its gap by more than this fraction of the particle's
        /// radius (less is left to the collision pass's push-out): a rope lying along a face without load would otherwise
        /// be held and released in turn through every pass.
        /// </summary>
        public const double HoldTolerance = 1e-4;

        /// <summary>Largest bend angle (rad) κ is evaluated at: a hairpin's tan(Δθ/2) is infinite.</summary>
        private const double MaxBend = Math.PI - 1e-3;

        /// <summary>Start of an iteration (after the residual is assembled): every contact's mobility and prescribed displacement, folded into R.</summary>
        public static void Prepare(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                c.ContactShiftX[i] = 0.0; c.ContactShiftY[i] = 0.0; c.ContactShiftZ[i] = 0.0;
                c.ContactLastDamping[i] = 0.0;
                Reshift(c, i);
            }
        }

        /// <summary>Recomputes contact i's tangential mobility and prescribed displacement for its state and moves its segments' residuals by the change.</summary>
        private static void Reshift(ChainState c, int i)
        {
            double ux, uy, uz;
            double w = c.InverseMass[i];
            double zeta = Damping(c, i);
            c.ContactMobility[i] = w / (1.0 + w * zeta);
            if (c.ContactActive[i]) Shift(c, i, zeta, out ux, out uy, out uz);
            else
            {
                // the impulse given back: along the normal as the displacement a push-out would make, along the surface as a force
                double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
                double gx = c.ContactImpulseX[i], gy = c.ContactImpulseY[i], gz = c.ContactImpulseZ[i];
                double gn = gx * nx + gy * ny + gz * nz;
                double un = -w * gn / c.ContactImpulseScale;
                ux = un * nx - w * (gx - gn * nx); uy = un * ny - w * (gy - gn * ny); uz = un * nz - w * (gz - gn * nz);
            }
            double dx = ux - c.ContactShiftX[i], dy = uy - c.ContactShiftY[i], dz = uz - c.ContactShiftZ[i];
            if (i > 0 && !c.Broken[i - 1]) { c.ResidualX[i - 1] += dx; c.ResidualY[i - 1] += dy; c.ResidualZ[i - 1] += dz; }
            if (i < c.SegmentCount && !c.Broken[i]) { c.ResidualX[i] -= dx; c.ResidualY[i] -= dy; c.ResidualZ[i] -= dz; }
            c.ContactShiftX[i] = ux; c.ContactShiftY[i] = uy; c.ContactShiftZ[i] = uz;
        }

        /// <summary>Contact i's friction damping ζ (kg): a sticking or sliding one's, none in a BDF2 substep (friction in contact makes the next substeps backward Euler, see <see cref="ChainState.HeldWithFriction"/>).</summary>
        private static double Damping(ChainState c, int i) => c.Bdf2Substep || !(c.ContactSticking[i] || c.ContactSliding[i]) ? 0.0 : c.ContactDamping[i];

        /// <summary>
        /// The displacement (m) held contact i prescribes in this iteration: along the normal onto the surface (−gap·c), and
        /// along the surface its friction damper's part, −w_t·(ζ·s₀ + G_t) (s₀ the slip before this iteration, G_t the
        /// friction applied in the substep's earlier ones).
        /// </summary>
        private static void Shift(ChainState c, int i, double zeta, out double ux, out double uy, out double uz)
        {
            double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
            double gap = c.ContactGap[i];
            ux = -gap * nx; uy = -gap * ny; uz = -gap * nz;
            if (zeta > 0.0)
            {
                Slip(c, i, out double sx, out double sy, out double sz);
                Friction(c, i, out double gx, out double gy, out double gz);
                double wt = c.ContactMobility[i];
                ux -= wt * (zeta * sx + gx);
                uy -= wt * (zeta * sy + gy);
                uz -= wt * (zeta * sz + gz);
            }
        }

        /// <summary>The friction impulse (N·s²) contact i has applied so far in the substep, in its current tangent plane.</summary>
        private static void Friction(ChainState c, int i, out double fx, out double fy, out double fz)
        {
            fx = c.ContactFrictionX[i]; fy = c.ContactFrictionY[i]; fz = c.ContactFrictionZ[i];
            Tangential(c, i, ref fx, ref fy, ref fz);
        }

        /// <summary>Takes out of (x, y, z) its part along contact i's normal c: v − (v·c)c, the part in its tangent plane.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void Tangential(ChainState c, int i, ref double x, ref double y, ref double z)
        {
            double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
            double along = x * nx + y * ny + z * nz;
            x -= along * nx; y -= along * ny; z -= along * nz;
        }

        /// <summary>
        /// Contact particle i's tangential slip (m) so far in the substep: its displacement D less the collider's v_c·h,
        /// along the surface. Friction acts in backward-Euler substeps only (v = D/h), so the slip is h·(v − v_c): a
        /// sticking particle ends the substep (nearly) at rest on the collider.
        /// </summary>
        private static void Slip(ChainState c, int i, out double sx, out double sy, out double sz)
        {
            sx = c.DX[i] - (double)c.ContactSurfaceX[i]; sy = c.DY[i] - (double)c.ContactSurfaceY[i]; sz = c.DZ[i] - (double)c.ContactSurfaceZ[i];
            Tangential(c, i, ref sx, ref sy, ref sz);
        }

        /// <summary>The slip (m) contact i makes under this solution: the one so far plus the motion's part along the surface.</summary>
        private static void SlipAfter(ChainState c, int i, double mx, double my, double mz, out double sx, out double sy, out double sz)
        {
            Slip(c, i, out sx, out sy, out sz);
            double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
            double mn = mx * nx + my * ny + mz * nz;
            sx += mx - mn * nx; sy += my - mn * ny; sz += mz - mn * nz;
        }

        /// <summary>
        /// κ (see the class summary) at particle i for μ: tanh(μΔθ/2)/(μ tan(Δθ/2)) with Δθ the angle between its
        /// segments' directions; 1 at an end of the chain or beside a broken segment.
        /// </summary>
        public static double Kappa(ChainState c, int i, double mu)
        {
            if (i == 0 || i >= c.SegmentCount || c.Broken[i - 1] || c.Broken[i] || mu <= 0.0) return 1.0;
            double cos = (double)c.DirX[i - 1] * c.DirX[i] + (double)c.DirY[i - 1] * c.DirY[i] + (double)c.DirZ[i - 1] * c.DirZ[i];
            double bend = Math.Acos(Math.Max(-1.0, Math.Min(1.0, cos)));
            if (bend < 1e-6) return 1.0;
            double half = 0.5 * Math.Min(bend, MaxBend);
            return Math.Tanh(mu * half) / (mu * Math.Tan(half));
        }

        /// <summary>Particle i's motion (m) under this solution: W_i·pull, plus the displacement its contact prescribes when it is in the contact set.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static void Motion(ChainState c, int i, out double mx, out double my, out double mz)
        {
            SegmentForceSystem.Motion(c, i, out mx, out my, out mz);
            if (c.ContactCount == 0 || c.ContactCollider[i] < 0) return;
            mx += c.ContactShiftX[i]; my += c.ContactShiftY[i]; mz += c.ContactShiftZ[i];
        }

        /// <summary>
        /// The active-set pass over the contacts after a solve: a held contact whose normal impulse over the substep would
        /// pull is released (and gives back the impulse of the substep's earlier passes) and stays free for the rest of the
        /// substep, once it pulls without friction (one with a friction damper first loses it: a pulled contact has no cone,
        /// and the damper held it along the surface in the solve that said it pulls); a free one whose motion takes it past
        /// its gap (by more than <see cref="HoldTolerance"/>) is held again with the friction it had; and each held contact's
        /// friction is moved to its cone (<see cref="Coulomb"/>). Returns true when some state changed, so the system must be
        /// solved again (<paramref name="frictionChanged"/>: some friction did). Contacts are released only in the substep's
        /// <paramref name="first"/> iteration: in a later one a held contact has taken the chain's whole pull so far, and a
        /// release would give it back as a displacement far outside the linearisation (a light particle under a taut rope's
        /// pull would move metres).
        /// </summary>
        public static bool Update(ChainState c, bool first, out bool frictionChanged)
        {
            bool changed = false;
            frictionChanged = false;
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
                Motion(c, i, out double mx, out double my, out double mz);
                if (!c.ContactActive[i])
                {
                    // one released in this substep stays free in it (a contact with next to no load would cycle between the
                    // states; if it ends up inside the surface the collision pass pushes it out)
                    if (!c.ContactStopped[i] && -(nx * mx + ny * my + nz * mz) > c.ContactGap[i] + HoldTolerance * c.Radius[i])
                    {
                        c.ContactActive[i] = true;
                        Reshift(c, i);
                        changed = true;
                    }
                    continue;
                }
                SegmentForceSystem.Pull(c, i, out double px, out double py, out double pz);
                double m = 1.0 / c.InverseMass[i];
                // the substep's contact impulse with this iteration's, m·motion − pull
                IterationImpulse(c, i, m, mx, my, mz, px, py, pz, out double gx, out double gy, out double gz);
                gx += c.ContactImpulseX[i]; gy += c.ContactImpulseY[i]; gz += c.ContactImpulseZ[i];
                double normal = gx * nx + gy * ny + gz * nz;
                // a contact held through the first iteration stays held in the later ones (on the surface it does no work
                // even where it would pull; giving its impulse back would move the particle by the chain's whole pull)
                if (first && normal < -NegligibleNormal * c.ContactNormalScale)
                {
                    if (Damping(c, i) > 0.0)
                    {
                        // friction first: a contact the chain pulls has no cone, so it loses its friction and the system is
                        // solved again; it is released only if it still pulls without friction (released with the damper, both
                        // contacts of a 200 GPa rope on the sphere ended inside it and the push after the solve stored 1.0 J)
                        c.ContactDamping[i] = 0.0;
                        c.ContactSliding[i] = true;
                        c.ContactSticking[i] = false;
                        frictionChanged = true;
                    }
                    else
                    {
                        c.ContactActive[i] = false;
                        c.ContactStopped[i] = true;
                    }
                    Reshift(c, i);
                    changed = true;
                    continue;
                }
                // friction follows its cone in every iteration
                if (!c.Bdf2Substep && c.ContactStaticFriction[i] > 0f && Coulomb(c, i, mx, my, mz, Math.Max(normal, 0.0)))
                {
                    Reshift(c, i);
                    changed = true;
                    frictionChanged = true;
                }
            }
            if (changed) DropContactsWithoutMobility(c);
            return changed;
        }

        /// <summary>
        /// True when some contact released in this substep (<see cref="ChainState.ContactStopped"/>: it stays free for the rest
        /// of the substep's active-set passes) is driven by this solution past its gap by more than <see cref="HoldTolerance"/>:
        /// left to the collision pass after the last iteration, its push-out would stretch the segments at it outside the chain
        /// solve (a 200 GPa rope hitting the sphere at 1/90 s stored 0.04 J that way). The solver then iterates again.
        /// </summary>
        public static bool ReleasedInside(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (c.ContactActive[i] || !c.ContactStopped[i]) continue;
                Motion(c, i, out double mx, out double my, out double mz);
                if (-(c.ContactNX[i] * mx + c.ContactNY[i] * my + c.ContactNZ[i] * mz) > c.ContactGap[i] + HoldTolerance * c.Radius[i]) return true;
            }
            return false;
        }

        /// <summary>
        /// Coulomb's cone at held contact i under this solution (motion in m, substep normal impulse N in N·s², ≥ 0), in the
        /// passes of the first iteration. The friction is the damper's ζ|s| (s the slip over the substep under this
        /// solution); the cone is μ·κ·N (μ_s while it sticks, μ_k once it slides). Sticking: ζ is the stiff damper of
        /// <see cref="StickingDamping"/>; where that asks more than the cone (by more than <see cref="FrictionTolerance"/>)
        /// the contact slides, and a sliding contact's ζ is moved to the one whose friction is the cone, ζ·cone/(ζ|s|): the
        /// friction is then μ·κ·N opposing the slip, whatever the slip, and stays a damper (it can slow the slip, never
        /// reverse it: no energy gain). A sliding contact whose ζ reaches the sticking one sticks. A contact without a
        /// friction state yet (new) sticks. Returns true when ζ changed (the system is solved again).
        /// </summary>
        private static bool Coulomb(ChainState c, int i, double mx, double my, double mz, double normal)
        {
            // no friction under a normal impulse below NegligibleNormal of the largest one (following it would only make the
            // passes run out)
            if (normal < NegligibleNormal * c.ContactNormalScale)
            {
                if (c.ContactDamping[i] == 0.0 && c.ContactSliding[i]) return false;
                c.ContactDamping[i] = 0.0;
                c.ContactSliding[i] = true;
                c.ContactSticking[i] = false;
                return true;
            }
            if (!c.ContactSticking[i] && !c.ContactSliding[i])
            {
                Stick(c, i, normal);
                return true;
            }
            SlipAfter(c, i, mx, my, mz, out double sx, out double sy, out double sz);
            double slip = Math.Sqrt(sx * sx + sy * sy + sz * sz);
            bool sliding = c.ContactSliding[i];
            float mu = sliding ? c.ContactKineticFriction[i] : c.ContactStaticFriction[i];
            double cone = mu * Kappa(c, i, mu) * normal;
            double stiff = StickingDamping(c, i, normal);
            double zeta = c.ContactDamping[i];
            double force = zeta * slip;
            double next;
            if (force > (1.0 + FrictionTolerance) * cone)
            {
                if (!sliding)
                {
                    // leaves the static cone: slides with the kinetic one
                    float kinetic = c.ContactKineticFriction[i];
                    cone = kinetic * Kappa(c, i, kinetic) * normal;
                    c.ContactLastDamping[i] = 0.0;
                    next = zeta * cone / force;
                }
                else next = Secant(c, i, zeta, force, cone);
            }
            else if (sliding && force < (1.0 - FrictionTolerance) * cone)
            {
                // a contact without friction (ζ 0: its normal impulse was negligible in the pass before) takes the damper whose
                // friction is its cone at this slip, not the sticking one: going from 0 to sticking and back made contacts
                // cycle until the passes ran out (64, traced on a 16-segment 1 GPa rope on the sphere of the stability sweep)
                next = force > 0.0 ? Math.Min(stiff, Secant(c, i, zeta, force, cone)) : slip > 0.0 ? Math.Min(stiff, cone / slip) : stiff;
            }
            else if (!sliding && Math.Abs(zeta - stiff) > 0.5 * stiff)
            {
                // a sticking contact's damper follows its normal impulse only roughly (it stiffens the cone's edge, it is no
                // friction force of its own): every change makes the system be solved again
                next = stiff;
            }
            else
            {
                return false;
            }
            c.ContactDamping[i] = next;
            c.ContactSliding[i] = next < stiff;
            c.ContactSticking[i] = !c.ContactSliding[i];
            return true;
        }

        /// <summary>Largest factor by which one pass's secant step may change a sliding contact's ζ.</summary>
        public const double MaxSecantFactor = 1e3;

        /// <summary>
        /// The next ζ (kg) of sliding contact i, whose damper ζ gave the friction ζ|s| = force (N·s²) against the cone C
        /// (N·s²). The plain update ζ·C/force (the damper whose friction would be the cone at this slip) is a fixed point
        /// that converges slowly where many contacts slide together: each one's ζ changes the slip of all, and with the wrap's
        /// friction close to the load's pull it contracts by about (friction / pull) per pass (0.98 at 2 % past the capstan
        /// ratio). The friction f(ζ) = ζ|s(ζ)| of the coupled solve rises with ζ and flattens towards the pull, so the secant
        /// through this pass's (ζ, f) and the pass before's solves f(ζ) = C in a few passes (the contacts of a wrap move
        /// their ζ together, which makes it nearly a one-dimensional root). The secant step is taken when the slope is
        /// positive and it goes the way the plain update goes, by at most <see cref="MaxSecantFactor"/>; otherwise the plain
        /// update. Either way ζ stays a damper's (it never reverses the slip, never adds energy).
        /// </summary>
        private static double Secant(ChainState c, int i, double zeta, double force, double cone)
        {
            double plain = zeta * cone / force;
            double lastZeta = c.ContactLastDamping[i], lastForce = c.ContactLastForce[i];
            c.ContactLastDamping[i] = zeta;
            c.ContactLastForce[i] = force;
            if (!(lastZeta > 0.0) || lastZeta == zeta) return plain;
            double slope = (force - lastForce) / (zeta - lastZeta);
            if (!(slope > 0.0)) return plain;
            double next = zeta + (cone - force) / slope;
            if (!double.IsFinite(next) || (next - zeta) * (plain - zeta) <= 0.0) return plain;
            return Math.Max(zeta / MaxSecantFactor, Math.Min(zeta * MaxSecantFactor, next));
        }

        /// <summary>
        /// After the substep's last iteration: the largest normal impulse of the held contacts
        /// (<see cref="ChainState.ContactNormalScale"/>) and whether friction acts on each: one not pressed onto a surface
        /// with friction loses its friction state; the others keep theirs (ζ included: a sliding contact's ζ is the next substep's first guess) and make the next
        /// substep backward Euler (<see cref="ChainState.HeldWithFriction"/>).
        /// </summary>
        public static void DecideFriction(ChainState c)
        {
            c.HeldWithFriction = false;
            c.ContactNormalScale = 0.0;
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (!c.ContactActive[i]) continue;
                double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
                double normal = c.ContactImpulseX[i] * nx + c.ContactImpulseY[i] * ny + c.ContactImpulseZ[i] * nz;
                c.ContactNormalScale = Math.Max(c.ContactNormalScale, normal);
                if (!(normal > 0.0) || c.ContactStaticFriction[i] == 0f)
                {
                    c.ContactSticking[i] = false;
                    c.ContactSliding[i] = false;
                    continue;
                }
                c.HeldWithFriction = true;
                if (!c.ContactSticking[i] && !c.ContactSliding[i]) Stick(c, i, normal);
            }
        }

        /// <summary>
        /// A sticking contact's damping ζ = μ_s·κ·N/ε (kg) under normal impulse N (N·s²), ε the slip of <see cref="CreepSpeed"/>
        /// over the substep: the friction reaches its cone when the particle creeps that fast.
        /// </summary>
        private static double StickingDamping(ChainState c, int i, double normal)
        {
            float stat = c.ContactStaticFriction[i];
            return stat * Kappa(c, i, stat) * normal / (CreepSpeed * c.Substep);
        }

        /// <summary>Contact i sticks under normal impulse N (N·s²), with the damping of <see cref="StickingDamping"/>.</summary>
        private static void Stick(ChainState c, int i, double normal)
        {
            c.ContactSticking[i] = true;
            c.ContactSliding[i] = false;
            c.ContactDamping[i] = StickingDamping(c, i, normal);
        }

        /// <summary>
        /// A held contact that would leave one of its segments with no mobility along it (the other end pinned, no
        /// compliance) would make that row singular: it is dropped.
        /// </summary>
        public static void DropContactsWithoutMobility(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (!c.ContactActive[i] || HasAxialMobility(c, i)) continue;
                c.ContactActive[i] = false;
                Reshift(c, i);
            }
        }

        private static bool HasAxialMobility(ChainState c, int i) =>
            (i == 0 || AxialMobilityLeft(c, i - 1)) && (i >= c.SegmentCount || AxialMobilityLeft(c, i));

        /// <summary>True when segment j keeps mobility (or compliance) along its direction with its ends' contacts held.</summary>
        private static bool AxialMobilityLeft(ChainState c, int j)
        {
            if (c.Broken[j] || c.Compliance[j] > 0f) return true;
            double nx = c.DirX[j], ny = c.DirY[j], nz = c.DirZ[j];
            double along = SegmentForceSystem.AlongMobility(c, j, nx, ny, nz) + SegmentForceSystem.AlongMobility(c, j + 1, nx, ny, nz);
            return along > 1e-12 * ((double)c.InverseMass[j] + c.InverseMass[j + 1]);
        }

        /// <summary>
        /// The contact impulse (N·s², the solve's h_eff² times the force) of contact particle i (mass m, kg) in this iteration,
        /// motion (m) and pull (N·s²) given: m·motion − pull, with the motion along the normal scaled by (h_eff/h)²
        /// (<see cref="ChainState.ContactImpulseScale"/>): it is taken as backward Euler takes a push-out, as the force
        /// m·motion/h² (a particle resting on a surface is pushed out by h²·g each substep in either scheme), so its impulse
        /// in the solve's units is h_eff²/h² of m·motion (in backward Euler the scale is 1).
        /// </summary>
        private static void IterationImpulse(ChainState c, int i, double m, double mx, double my, double mz, double px, double py, double pz,
            out double ix, out double iy, out double iz)
        {
            double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
            double along = (c.ContactImpulseScale - 1.0) * (mx * nx + my * ny + mz * nz);
            ix = m * (mx + along * nx) - px; iy = m * (my + along * ny) - py; iz = m * (mz + along * nz) - pz;
        }

        /// <summary>
        /// The friction part of the line search's objective (<see cref="ChainLineSearch"/>) at step s along this iteration
        /// (h²·ΔΦ, N·m·s²), and its slope at s = 0 (<paramref name="slope"/>): a held contact with friction damper ζ adds
        /// ½ζ|s_slip|² to the implicit step's objective (its gradient is the damper's −ζ·s_slip), and the friction impulse
        /// G_t the substep had applied before the iteration is a force on the particle like the chain's pull, so along the
        /// iteration's tangential motion δ_t the objective changes by s·δ_t·G_t + ζ(s·s₀·δ_t + ½s²|δ_t|²), s₀ the slip before
        /// the iteration. With friction in it, a step the line search accepts lowers the energy the friction dissipates
        /// against, not only the chain's.
        /// </summary>
        public static double FrictionChange(ChainState c, double s, out double slope)
        {
            double change = 0.0;
            slope = 0.0;
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (!c.ContactActive[i] || c.ContactStaticFriction[i] == 0f) continue;
                double zeta = Damping(c, i);
                double tx = c.MotionX[i], ty = c.MotionY[i], tz = c.MotionZ[i];
                Tangential(c, i, ref tx, ref ty, ref tz);
                // the slip before the iteration: the slip now less the iteration's tangential motion
                Slip(c, i, out double sx, out double sy, out double sz);
                sx -= tx; sy -= ty; sz -= tz;
                Before(c, i, out double gx, out double gy, out double gz);
                double linear = tx * (gx + zeta * sx) + ty * (gy + zeta * sy) + tz * (gz + zeta * sz);
                slope += linear;
                change += s * linear + 0.5 * s * s * zeta * (tx * tx + ty * ty + tz * tz);
            }
            return change;
        }

        /// <summary>True when some contact of the solve is held on a surface with friction.</summary>
        public static bool FrictionInSolve(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (c.ContactActive[i] && c.ContactStaticFriction[i] > 0f) return true;
            }
            return false;
        }

        /// <summary>Held contact i's contact impulse before this iteration (N·s²), along its tangent plane: the substep's less the iteration's m·motion − pull.</summary>
        private static void Before(ChainState c, int i, out double gx, out double gy, out double gz)
        {
            RecordedIterationImpulse(c, i, out double ix, out double iy, out double iz);
            gx = c.ContactImpulseX[i] - ix; gy = c.ContactImpulseY[i] - iy; gz = c.ContactImpulseZ[i] - iz;
            Tangential(c, i, ref gx, ref gy, ref gz);
        }

        /// <summary>Contact i's impulse of this iteration (N·s²) from its recorded motion and this iteration's pull (what <see cref="Finish"/> added).</summary>
        private static void RecordedIterationImpulse(ChainState c, int i, out double ix, out double iy, out double iz)
        {
            SegmentForceSystem.Pull(c, i, out double px, out double py, out double pz);
            IterationImpulse(c, i, 1.0 / c.InverseMass[i], c.MotionX[i], c.MotionY[i], c.MotionZ[i], px, py, pz, out ix, out iy, out iz);
        }

        /// <summary>
        /// The line search took back (1 − s) of the iteration (<see cref="ChainLineSearch.Shorten"/>; called before it scales
        /// the motions and steps): each contact's impulse of the iteration, its friction (the damper's −ζ·s on the shortened
        /// slip, read after the positions are shortened: see <see cref="FinishShortened"/>) and the normal shift taken out
        /// of the solve displacement shrink with it.
        /// </summary>
        public static void Shorten(ChainState c, double s)
        {
            double back = 1.0 - s;
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                RecordedIterationImpulse(c, i, out double ix, out double iy, out double iz);
                c.ContactImpulseX[i] -= back * ix; c.ContactImpulseY[i] -= back * iy; c.ContactImpulseZ[i] -= back * iz;
                double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
                double along = back * (c.ContactShiftX[i] * nx + c.ContactShiftY[i] * ny + c.ContactShiftZ[i] * nz);
                c.SolveDX[i] += along * nx; c.SolveDY[i] += along * ny; c.SolveDZ[i] += along * nz;
            }
        }

        /// <summary>After <see cref="ChainLineSearch.Shorten"/> moved the particles: each held contact's friction, −ζ·s on the slip it now ends with.</summary>
        public static void FinishShortened(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                double zeta = c.ContactActive[i] ? Damping(c, i) : 0.0;
                if (!(zeta > 0.0)) continue;
                Slip(c, i, out double sx, out double sy, out double sz);
                c.ContactFrictionX[i] = -zeta * sx; c.ContactFrictionY[i] = -zeta * sy; c.ContactFrictionZ[i] = -zeta * sz;
            }
        }

        /// <summary>
        /// Contact particle i makes the motion (mx, my, mz) of this solution (m): adds the contact impulse to the substep's
        /// and takes the displacement the contact imposes out of the solve displacement Δ of the second-order integrator,
        /// which takes it as backward Euler does a push-out (see <see cref="Rope"/>'s integration): its part along the normal.
        /// Friction stays in Δ: it is a force like the chain's (a viscous one, see <see cref="Slip"/>).
        /// </summary>
        public static void Finish(ChainState c, int i, double px, double py, double pz, double mx, double my, double mz)
        {
            double w = c.InverseMass[i], m = 1.0 / w;
            IterationImpulse(c, i, m, mx, my, mz, px, py, pz, out double ix, out double iy, out double iz);
            c.ContactImpulseX[i] += ix; c.ContactImpulseY[i] += iy; c.ContactImpulseZ[i] += iz;
            double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
            // the friction of the substep so far: the damper's −ζ·s on the slip it ends with (sticking or sliding)
            double zeta = c.ContactActive[i] ? Damping(c, i) : 0.0;
            if (zeta > 0.0)
            {
                SlipAfter(c, i, mx, my, mz, out double sx, out double sy, out double sz);
                c.ContactFrictionX[i] = -zeta * sx; c.ContactFrictionY[i] = -zeta * sy; c.ContactFrictionZ[i] = -zeta * sz;
            }
            else
            {
                c.ContactFrictionX[i] = 0.0; c.ContactFrictionY[i] = 0.0; c.ContactFrictionZ[i] = 0.0;
            }
            double ux = c.ContactShiftX[i], uy = c.ContactShiftY[i], uz = c.ContactShiftZ[i];
            double along = ux * nx + uy * ny + uz * nz;
            double ex = along * nx, ey = along * ny, ez = along * nz;
            c.SolveDX[i] -= ex; c.SolveDY[i] -= ey; c.SolveDZ[i] -= ez;
        }
    }
}
