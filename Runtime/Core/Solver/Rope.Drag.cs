using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// Drag (issue 15 item 4): forces per metre of rope on its velocity relative to the air, v_rel = v − <see cref="RopeSettings.Wind"/>,
    /// <list type="bullet">
    /// <item>viscous: f = −c·v_rel (<see cref="RopeSettings.ViscousDrag"/>, N·s/m²);</item>
    /// <item>quadratic across the rope: f = −½·ρ·C_d·2R·|v_rel⊥|·v_rel⊥ (<see cref="RopeSettings.DragCoefficient"/>);</item>
    /// <item>skin friction along it: f = −½·ρ·C_f·2πR·|v_rel∥|·v_rel∥ (<see cref="RopeSettings.SkinFriction"/>).</item>
    /// </list>
    /// Particle i carries the drag of its share ℓ_i of the rope (half of each adjacent segment's rest length) over its mass m_i
    /// (loads included: they add mass, not drag area), with the rest radius R: k = c·ℓ_i/m_i (1/s) and so on. Rest values keep the
    /// coefficients constant while the rope stretches: the projected area 2r·l of a stretched, Poisson-thinned rope is
    /// 2R·L·(1 + ε)^(1−ν), a few per cent at the strains of a lanyard, well inside the uncertainty of C_d.
    /// <para>Every term is a force in the implicit step, never a kick: the scheme's acceleration a_{n+1} includes it, so the
    /// position and the velocity of BDF2 (x_{n+1} = (4x_n − x_{n−1})/3 + h_eff·v_{n+1}, v_{n+1} = (4v_n − v_{n−1})/3 + h_eff·a_{n+1},
    /// h_eff = 2h/3) stay consistent and its history needs no boost (<see cref="BoostHistory"/> is for host changes). With
    /// v_{n+1} = V + h_eff·(a_c + a_drag), V the velocity of the prediction (history and gravity), a_c the chain solve's:</para>
    /// <list type="bullet">
    /// <item>The viscous term is exactly implicit, −c·ℓ/m·(v_{n+1} − u): the prediction divides V − u by 1 + h_eff·k and the chain
    /// solve sees each particle's mobility w/(1 + h_eff·k) (<see cref="FoldViscousDrag"/>), so its constraint forces are damped by the
    /// drag within the substep too. This is the implicit Euler / BDF2 step of the whole system: dissipative at any c, second
    /// order with BDF2, and the tensions it reads are the true ones.</item>
    /// <item>The quadratic terms are linearised: K = k⊥(I − ttᵀ) + k∥ttᵀ with k⊥ = ½ρC_d·2R·ℓ/m·|v*⊥ − u⊥| (likewise k∥),
    /// taken at the extrapolated end velocity v* = 2v_n − v_{n−1} (BDF2; v_n in a backward-Euler substep) and the tangent t of the
    /// predicted positions (central difference); then −K·(Ṽ − u) acts implicitly on the prediction, Ṽ − u = (I + h_eff·K)⁻¹(V − u).
    /// For any K ≥ 0 that only shrinks the relative velocity (at 90 km/s after a teleport too); it is exact for a particle the
    /// chain does not pull (free fall: the terminal velocity), and it misses only the drag on the chain's own velocity change of the
    /// substep, a force error h_eff·K·a_c (first order in h, tiny at air-drag strengths).</item>
    /// </list>
    /// Off (<see cref="RopeSettings.HasDrag"/> false) nothing here runs.
    /// </summary>
    public sealed partial class Rope
    {
        // ℓ_i/m_i of each particle (m/kg), refreshed at the start of every host step with drag
        private double[] dragRate;
        // the viscous fold: the inverse masses before it, and the ones the chain solve uses (a compliant pin restores these)
        private float[] dragInverseMass, dragSolveInverseMass;
        // the quadratic drag's acceleration on each particle in the current substep (m/s²), for the work
        private float[] dragAccelX, dragAccelY, dragAccelZ;
        private bool viscousFolded;
        private double dragWork;

        /// <summary>True when the quadratic terms act (ρ &gt; 0 and C_d or C_f &gt; 0).</summary>
        private bool QuadraticDrag => settings.AirDensity > 0f && (settings.DragCoefficient > 0f || settings.SkinFriction > 0f);

        /// <summary>
        /// Work in joules the drag forces did on the rope since it was built: Σ f·d over the substeps (f the particle's drag force,
        /// d its displacement). Negative as the air slows the rope, positive while a wind drives it; 0 without drag.
        /// </summary>
        public double DragWork => dragWork;

        /// <summary>
        /// Start of a host step with drag: allocates the drag state once (the first step with drag) and takes each particle's
        /// share of the rope over its mass, ℓ_i/m_i (m/kg; ℓ_i half of each adjacent segment's rest length, m_i with its load).
        /// </summary>
        private void PrepareDrag()
        {
            int n = chain.ParticleCount, segments = chain.SegmentCount;
            if (dragRate == null)
            {
                dragRate = new double[n];
                dragInverseMass = new float[n]; dragSolveInverseMass = new float[n];
                dragAccelX = new float[n]; dragAccelY = new float[n]; dragAccelZ = new float[n];
            }
            float[] rest = chain.RestLength, mass = chain.Mass;
            for (int i = 0; i < n; i++)
            {
                double share = 0.0;
                if (i > 0) share += rest[i - 1];
                if (i < segments) share += rest[i];
                dragRate[i] = 0.5 * share / mass[i];
            }
        }

        /// <summary>
        /// After the prediction (second-order run: d, base and d_pred of <see cref="PredictSecondOrder"/>; else the velocity and d
        /// of <see cref="Predict"/>): replaces each free particle's predicted velocity V by u + (I + s·(k_v I + K))⁻¹(V − u) and
        /// moves its predicted displacement with it (by s·ΔV; s = h_eff, the scheme's effective step, s; h the substep, s; g m/s²).
        /// </summary>
        private void PredictDrag(bool secondOrder, bool bdf2, float h, double hd, double s, Float3 g)
        {
            if (QuadraticDrag) PredictQuadraticDrag(secondOrder, bdf2, h, hd, s, g);
            else PredictViscousDrag(secondOrder, h, hd, s);
        }

        /// <summary><see cref="PredictDrag"/> with the viscous term alone: V − u is divided by 1 + s·c·ℓ/m.</summary>
        private void PredictViscousDrag(bool secondOrder, float h, double hd, double s)
        {
            int n = chain.ParticleCount;
            float[] dx = chain.DX, dy = chain.DY, dz = chain.DZ, vx = chain.VelX, vy = chain.VelY, vz = chain.VelZ;
            float[] qx = chain.PredictedDX, qy = chain.PredictedDY, qz = chain.PredictedDZ;
            double[] bx = chain.BaseVelX, by = chain.BaseVelY, bz = chain.BaseVelZ, rate = dragRate;
            bool[] kinematic = chain.Kinematic;
            double sc = s * settings.ViscousDrag, invH = 1.0 / hd;
            Float3 wind = settings.Wind;
            double ux = wind.X, uy = wind.Y, uz = wind.Z;
            for (int i = 0; i < n; i++)
            {
                if (kinematic[i]) continue;
                double kept = 1.0 / (1.0 + sc * rate[i]);
                if (secondOrder)
                {
                    double wx = bx[i] + dx[i] * invH, wy = by[i] + dy[i] * invH, wz = bz[i] + dz[i] * invH;
                    double nx = ux + (wx - ux) * kept, ny = uy + (wy - uy) * kept, nz = uz + (wz - uz) * kept;
                    dx[i] = (float)(dx[i] + s * (nx - wx)); dy[i] = (float)(dy[i] + s * (ny - wy)); dz[i] = (float)(dz[i] + s * (nz - wz));
                    bx[i] = nx - dx[i] * invH; by[i] = ny - dy[i] * invH; bz[i] = nz - dz[i] * invH;
                    qx[i] = dx[i]; qy[i] = dy[i]; qz[i] = dz[i];
                }
                else
                {
                    vx[i] = (float)(ux + (vx[i] - ux) * kept); vy[i] = (float)(uy + (vy[i] - uy) * kept); vz[i] = (float)(uz + (vz[i] - uz) * kept);
                    dx[i] = vx[i] * h; dy[i] = vy[i] * h; dz[i] = vz[i] * h;
                }
            }
        }

        /// <summary><see cref="PredictDrag"/> with the quadratic terms (and the viscous one if set), per particle along and across its tangent.</summary>
        private void PredictQuadraticDrag(bool secondOrder, bool bdf2, float h, double hd, double s, Float3 g)
        {
            int n = chain.ParticleCount, segments = chain.SegmentCount;
            float[] px = chain.PrevX, py = chain.PrevY, pz = chain.PrevZ, dx = chain.DX, dy = chain.DY, dz = chain.DZ;
            float[] vx = chain.VelX, vy = chain.VelY, vz = chain.VelZ;
            float[] qx = chain.PredictedDX, qy = chain.PredictedDY, qz = chain.PredictedDZ;
            double[] bx = chain.BaseVelX, by = chain.BaseVelY, bz = chain.BaseVelZ, rate = dragRate;
            float[] ax = dragAccelX, ay = dragAccelY, az = dragAccelZ;
            bool[] kinematic = chain.Kinematic, broken = chain.Broken;
            double viscous = settings.ViscousDrag, rho = settings.AirDensity, radius = settings.Radius;
            double across = rho * settings.DragCoefficient * radius;          // ½·ρ·C_d·2R, kg/m²
            double along = rho * settings.SkinFriction * Math.PI * radius;    // ½·ρ·C_f·2πR, kg/m²
            Float3 wind = settings.Wind;
            double ux = wind.X, uy = wind.Y, uz = wind.Z, invH = 1.0 / hd;
            // the predicted position of the particle before, as it was before its drag (the tangent's left end)
            float lx = 0f, ly = 0f, lz = 0f;
            for (int i = 0; i < n; i++)
            {
                float cx = px[i] + dx[i], cy = py[i] + dy[i], cz = pz[i] + dz[i];
                float leftX = lx, leftY = ly, leftZ = lz;
                lx = cx; ly = cy; lz = cz;
                ax[i] = 0f; ay[i] = 0f; az[i] = 0f;
                if (kinematic[i]) continue;
                double perMass = rate[i], kv = viscous * perMass;
                // V: the prediction's velocity (history and gravity), relative to the air
                double wx, wy, wz;
                if (secondOrder) { wx = bx[i] + dx[i] * invH; wy = by[i] + dy[i] * invH; wz = bz[i] + dz[i] * invH; }
                else { wx = vx[i]; wy = vy[i]; wz = vz[i]; }
                double rx = wx - ux, ry = wy - uy, rz = wz - uz;
                // tangent of the predicted positions (central difference; one-sided at an end or a break; none when folded flat)
                float rightX = cx, rightY = cy, rightZ = cz;
                if (i < segments && !broken[i]) { rightX = px[i + 1] + dx[i + 1]; rightY = py[i + 1] + dy[i + 1]; rightZ = pz[i + 1] + dz[i + 1]; }
                if (i == 0 || broken[i - 1]) { leftX = cx; leftY = cy; leftZ = cz; }
                double tx = (double)rightX - leftX, ty = (double)rightY - leftY, tz = (double)rightZ - leftZ;
                double span = Math.Sqrt(tx * tx + ty * ty + tz * tz);
                double unit = span > 0.0 && span <= double.MaxValue ? 1.0 / span : 0.0;
                tx *= unit; ty *= unit; tz *= unit;
                // v*: the end velocity the quadratic coefficients are taken at, relative to the air (BDF2: 2v_n − v_{n−1} = 3M − 2v_n,
                // M = V − h_eff·g; backward Euler: v_n)
                double ex, ey, ez;
                if (bdf2) { ex = 3.0 * (wx - s * g.X) - 2.0 * vx[i]; ey = 3.0 * (wy - s * g.Y) - 2.0 * vy[i]; ez = 3.0 * (wz - s * g.Z) - 2.0 * vz[i]; }
                else if (secondOrder) { ex = vx[i]; ey = vy[i]; ez = vz[i]; }
                else { ex = wx - h * g.X; ey = wy - h * g.Y; ez = wz - h * g.Z; }
                ex -= ux; ey -= uy; ez -= uz;
                double starAlong = ex * tx + ey * ty + ez * tz;
                double starAcross = Math.Sqrt(Math.Max(ex * ex + ey * ey + ez * ez - starAlong * starAlong, 0.0));
                double kAlong = along * perMass * Math.Abs(starAlong), kAcross = across * perMass * starAcross;
                double fAlong = 1.0 / (1.0 + s * (kv + kAlong)), fAcross = 1.0 / (1.0 + s * (kv + kAcross));
                // split V − u along and across the tangent, and shrink each part
                double r = rx * tx + ry * ty + rz * tz;
                double mx = r * tx, my = r * ty, mz = r * tz;
                double ox = rx - mx, oy = ry - my, oz = rz - mz;
                mx *= fAlong; my *= fAlong; mz *= fAlong;
                ox *= fAcross; oy *= fAcross; oz *= fAcross;
                ax[i] = (float)-(kAlong * mx + kAcross * ox);
                ay[i] = (float)-(kAlong * my + kAcross * oy);
                az[i] = (float)-(kAlong * mz + kAcross * oz);
                double nx = ux + mx + ox, ny = uy + my + oy, nz = uz + mz + oz; // Ṽ
                if (secondOrder)
                {
                    dx[i] = (float)(dx[i] + s * (nx - wx)); dy[i] = (float)(dy[i] + s * (ny - wy)); dz[i] = (float)(dz[i] + s * (nz - wz));
                    bx[i] = nx - dx[i] * invH; by[i] = ny - dy[i] * invH; bz[i] = nz - dz[i] * invH;
                    qx[i] = dx[i]; qy[i] = dy[i]; qz[i] = dz[i];
                }
                else
                {
                    vx[i] = (float)nx; vy[i] = (float)ny; vz[i] = (float)nz;
                    dx[i] = vx[i] * h; dy[i] = vy[i] * h; dz[i] = vz[i] * h;
                }
            }
        }

        /// <summary>
        /// Folds the viscous drag into the chain solve: each free particle's inverse mass becomes w/(1 + s·c·ℓ/m) (s = h_eff, s), the
        /// mass the implicit step sees when the drag −c·ℓ·(v_{n+1} − u) acts on the end velocity. <see cref="UnfoldViscousDrag"/> restores them.
        /// </summary>
        private void FoldViscousDrag(double s)
        {
            int n = chain.ParticleCount;
            float[] w = chain.InverseMass, saved = dragInverseMass, solve = dragSolveInverseMass;
            double[] rate = dragRate;
            double sc = s * settings.ViscousDrag;
            Array.Copy(w, saved, n);
            for (int i = 0; i < n; i++) w[i] = (float)(w[i] / (1.0 + sc * rate[i]));
            Array.Copy(w, solve, n);
            viscousFolded = true;
        }

        private void UnfoldViscousDrag()
        {
            Array.Copy(dragInverseMass, chain.InverseMass, chain.ParticleCount);
            viscousFolded = false;
        }

        /// <summary>The inverse mass (1/kg) the chain solve uses for particle i: with the viscous drag folded in while it is.</summary>
        private float SolveInverseMass(int i) => viscousFolded ? dragSolveInverseMass[i] : 1f / chain.Mass[i];

        /// <summary>Adds the substep's drag work Σ f·d (J): f/m = the quadratic drag's acceleration − c·ℓ/m·(v_{n+1} − u).</summary>
        private void AccumulateDragWork()
        {
            bool quadratic = QuadraticDrag;
            int n = chain.ParticleCount;
            float[] dx = chain.DX, dy = chain.DY, dz = chain.DZ, vx = chain.VelX, vy = chain.VelY, vz = chain.VelZ, mass = chain.Mass;
            bool[] kinematic = chain.Kinematic;
            double[] rate = dragRate;
            double viscous = settings.ViscousDrag;
            Float3 wind = settings.Wind;
            double ux = wind.X, uy = wind.Y, uz = wind.Z, work = 0.0;
            for (int i = 0; i < n; i++)
            {
                if (kinematic[i]) continue;
                double kv = viscous * rate[i];
                double fx = -kv * (vx[i] - ux), fy = -kv * (vy[i] - uy), fz = -kv * (vz[i] - uz);
                if (quadratic) { fx += dragAccelX[i]; fy += dragAccelY[i]; fz += dragAccelZ[i]; }
                work += mass[i] * (fx * dx[i] + fy * dy[i] + fz * dz[i]);
            }
            if (double.IsFinite(work)) dragWork += work;
        }
    }
}
