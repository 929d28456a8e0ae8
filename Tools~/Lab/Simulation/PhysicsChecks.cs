using System;
using System.Collections.Generic;
using HookeRope.Lab.Scenarios;
using HookeRope.Mathematics;
using HookeRope.Radius;

namespace HookeRope.Lab.Simulation
{
    /// <summary>One measured quantity next to its analytic answer.</summary>
    public sealed class CheckResult
    {
        /// <summary>What is compared.</summary>
        public string Quantity;
        /// <summary>Unit of both values.</summary>
        public string Unit;
        /// <summary>Simulated value.</summary>
        public double Measured;
        /// <summary>Analytic value.</summary>
        public double Expected;
        /// <summary>Accepted relative error (or absolute, in Unit, when <see cref="Absolute"/>).</summary>
        public double Tolerance;
        /// <summary>True: the tolerance is absolute and <see cref="Expected"/> is a bound or target in Unit.</summary>
        public bool Absolute;
        /// <summary>Formula or source of the expected value.</summary>
        public string Formula;

        /// <summary>|measured − expected| / |expected| (or absolute difference when <see cref="Absolute"/>).</summary>
        public double Error => Absolute
            ? Math.Abs(Measured - Expected)
            : Math.Abs(Measured - Expected) / Math.Max(Math.Abs(Expected), 1e-30);

        /// <summary>True when the error is within tolerance and the measurement is finite.</summary>
        public bool Passed => double.IsFinite(Measured) && Error <= Tolerance;
    }

    /// <summary>
    /// The analytic answers of the built-in scenarios (physics-notes reference answers) and the
    /// matching measurements of a run. Shared by the summary, the report and the tests.
    /// </summary>
    public static class PhysicsChecks
    {
        /// <summary>Standard gravity used by the formulas: |scenario gravity| in m/s².</summary>
        static double G(Scenario s) => s.Gravity.Length;

        /// <summary>Peak arrest force of a massless linear lanyard, N: Mg + sqrt((Mg)² + 2Mgkh).</summary>
        public static double FallArrestForce(double mass, double g, double stiffness, double fallHeight)
        {
            double w = mass * g;
            return w + Math.Sqrt(w * w + 2 * w * stiffness * fallHeight);
        }

        /// <summary>Static elongation of a hanging rope with a load, m: (M + m/2)·g·L/(E·A).</summary>
        public static double StaticElongation(double load, double ropeMass, double g, double length, double axialStiffness) =>
            (load + ropeMass / 2) * g * length / axialStiffness;

        /// <summary>Root β of β·tan β = ratio (ratio = rope mass / load), first branch (0, π/2).</summary>
        public static double HeavyRopeBeta(double ratio)
        {
            double lo = 0, hi = Math.PI / 2 - 1e-12;
            for (int i = 0; i < 200; i++)
            {
                double mid = (lo + hi) / 2;
                if (mid * Math.Tan(mid) > ratio) hi = mid; else lo = mid;
            }
            return (lo + hi) / 2;
        }

        /// <summary>Fundamental period of a rope (fixed top) with a load, s: 2π·L/(β·c), c = sqrt(E·A/μ).</summary>
        public static double HeavyRopePeriod(double load, double ropeMass, double length, double axialStiffness)
        {
            double mu = ropeMass / length;
            double c = Math.Sqrt(axialStiffness / mu);
            double beta = HeavyRopeBeta(ropeMass / load);
            return 2 * Math.PI * length / (beta * c);
        }

        /// <summary>Poisson radius ratio r/R = sqrt(1 + 2ν(L/l − 1)) at strain ε = l/L − 1.</summary>
        public static double PoissonRadiusRatio(double nu, double strain) =>
            PoissonRadius.Ratio(1.0, 1.0 + strain, nu, slackKeepsRestRadius: false);

        /// <summary>Neck waist a = (sqrt(l² + 16 r²) − l)/4, written without cancellation, m.</summary>
        public static double NeckWaist(double length, double rMin) => NeckHyperbola.WaistRadius(length, rMin);

        /// <summary>Mean period (s) of a series sampled every <paramref name="dt"/> s, from upward crossings of its mean after <paramref name="skip"/> samples.</summary>
        public static double Period(double[] series, double dt, int skip = 0)
        {
            int n = series.Length;
            if (n - skip < 4) return double.NaN;
            double mean = 0;
            for (int i = skip; i < n; i++) mean += series[i];
            mean /= n - skip;
            double first = double.NaN, lastCrossing = double.NaN;
            int count = 0;
            for (int i = skip + 1; i < n; i++)
            {
                double a = series[i - 1] - mean, b = series[i] - mean;
                if (a < 0 && b >= 0)
                {
                    double t = (i - 1 + a / (a - b)) * dt;
                    if (count == 0) first = t;
                    lastCrossing = t;
                    count++;
                }
            }
            return count >= 2 ? (lastCrossing - first) / (count - 1) : double.NaN;
        }

        /// <summary>Mean of a series over whole periods after <paramref name="skip"/> samples.</summary>
        public static double Mean(double[] series, int skip)
        {
            double sum = 0;
            int count = 0;
            for (int i = skip; i < series.Length; i++)
            {
                sum += series[i];
                count++;
            }
            return count > 0 ? sum / count : double.NaN;
        }

        /// <summary>The checks that apply to a run (empty when the scenario has none).</summary>
        public static List<CheckResult> Evaluate(RunResult r)
        {
            var s = r.Scenario;
            var rope = s.Rope;
            double g = G(s), ea = rope.ResolvedAxialStiffness, length = rope.RestLength, mr = rope.Mass;
            double load = s.End.LoadMass;
            var list = new List<CheckResult>();
            switch (s.Expect.Check)
            {
                case "fall-arrest":
                    list.Add(new CheckResult
                    {
                        Quantity = "peak anchor force", Unit = "N", Measured = r.PeakTopForce, Tolerance = 0.05,
                        Expected = FallArrestForce(load, g, ea / length, s.Initial.FallHeight ?? length),
                        Formula = "Mg + sqrt((Mg)² + 2Mgkh), k = E·A/L",
                    });
                    break;
                case "static-hang":
                {
                    // Mean over the last whole periods of the residual axial oscillation (its centre is the static answer).
                    int whole = WholePeriods(r, HeavyRopePeriod(load, mr, length, ea), r.Steps / 2);
                    list.Add(new CheckResult
                    {
                        Quantity = "static elongation", Unit = "m", Tolerance = 0.02,
                        Measured = Mean(r.ElongationSeries, r.ElongationSeries.Length - whole),
                        Expected = StaticElongation(load, mr, g, length, ea), Formula = "(M + m/2)·g·L/(E·A)",
                    });
                    list.Add(new CheckResult
                    {
                        Quantity = "top tension", Unit = "N", Tolerance = 0.02,
                        Measured = Mean(r.TopTensionSeries, r.TopTensionSeries.Length - whole),
                        Expected = (load + mr) * g, Formula = "(M + m)·g",
                    });
                    break;
                }
                case "period":
                {
                    double expected = HeavyRopePeriod(load, mr, length, ea);
                    list.Add(new CheckResult
                    {
                        Quantity = "oscillation period", Unit = "s", Tolerance = 0.03, Expected = expected,
                        Measured = Period(r.LoadDrop, r.HostStep),
                        Formula = mr / load < 0.01 ? "2π·sqrt(M·L/(E·A))" : "2π·L/(β·c), β·tan β = m/M, c = sqrt(E·A/μ)",
                    });
                    int whole = WholePeriods(r, expected, r.Steps);
                    list.Add(new CheckResult
                    {
                        Quantity = "mean elongation", Unit = "m", Tolerance = 0.03,
                        Expected = StaticElongation(load, mr, g, length, ea),
                        Measured = Mean(r.ElongationSeries, r.ElongationSeries.Length - whole), Formula = "(M + m/2)·g·L/(E·A)",
                    });
                    break;
                }
                case "amplitude":
                    AddAmplitudeChecks(r, list, load, mr, g, length, ea);
                    break;
                case "rebound":
                    AddReboundChecks(r, list, load, g, ea / length);
                    break;
                case "snatch":
                    AddSnatchChecks(r, list, load, g, ea / length);
                    break;
                case "settle":
                    AddSettleChecks(r, list);
                    break;
                case "catenary":
                {
                    var start = ScenarioGeometry.StartPosition(s);
                    var end = ScenarioGeometry.EndPosition(s);
                    double span = (end - start).Length;
                    double a = ScenarioGeometry.CatenaryParameter(span, length);
                    list.Add(new CheckResult
                    {
                        Quantity = "sag", Unit = "m", Measured = Sag(r), Tolerance = 0.01,
                        Expected = ScenarioGeometry.CatenarySag(span, length), Formula = "a·cosh(D/2a) − a, 2a·sinh(D/2a) = S",
                    });
                    list.Add(new CheckResult
                    {
                        Quantity = "horizontal tension", Unit = "N", Tolerance = 0.02, Expected = rope.ResolvedLinearDensity * g * a,
                        Measured = Math.Abs(Horizontal(r.StartPinForce, s)), Formula = "H = μ·g·a",
                    });
                    break;
                }
                case "poisson":
                {
                    double strain = FinalElongation(r) / length;
                    list.Add(new CheckResult
                    {
                        Quantity = "radius ratio r/R", Unit = "", Tolerance = 0.01, Absolute = false,
                        Expected = PoissonRadiusRatio(rope.PoissonRatio, strain), Measured = MidRadius(r) / rope.Radius,
                        Formula = "sqrt(1 + 2ν(L/l − 1))",
                    });
                    break;
                }
                case "neck":
                {
                    double rMin = rope.NeckRadiusFraction * rope.Radius;
                    double strain = FinalElongation(r) / length;
                    list.Add(new CheckResult
                    {
                        Quantity = "neck radius below r_min", Unit = "m", Absolute = true, Tolerance = 0,
                        Expected = 0, Measured = Math.Max(0, LastNeckRadius(r) - rMin), Formula = "r_neck ≤ r_min once r < r_min",
                    });
                    list.Add(new CheckResult
                    {
                        Quantity = "thinnest point (fraction of L)", Unit = "", Absolute = true, Tolerance = 1.5 / rope.Segments,
                        Expected = rope.DefectPosition, Measured = ThinnestFraction(r), Formula = "at the defect",
                    });
                    list.Add(new CheckResult
                    {
                        Quantity = "radius ratio away from the neck", Unit = "", Tolerance = 0.02,
                        Expected = PoissonRadiusRatio(rope.PoissonRatio, strain), Measured = FarRadius(r) / rope.Radius,
                        Formula = "sqrt(1 + 2ν(L/l − 1))",
                    });
                    break;
                }
                case "absorber":
                    AddAbsorberChecks(r, list, load, g, ea / length);
                    break;
                case "plastic":
                    AddPlasticChecks(r, list);
                    break;
                case "fracture":
                    list.Add(new CheckResult
                    {
                        Quantity = "tension at break", Unit = "N", Tolerance = 0.05, Measured = r.BreakTension,
                        Expected = ea * rope.BreakStrain, Formula = "E·A·ε_break",
                    });
                    break;
                case "collision":
                {
                    // depth against each particle's collision radius (the radius model thins the cord under strain)
                    list.Add(new CheckResult
                    {
                        Quantity = "deepest penetration", Unit = "m", Absolute = true, Tolerance = 0.01 * SmallestRadius(r), Expected = 0,
                        Measured = Math.Max(0, Penetration(r)), Formula = "no particle inside the collider (1 % of the collision radius)",
                    });
                    double path = WrappedPathLength(s);
                    list.Add(new CheckResult
                    {
                        Quantity = "rope length over the bar", Unit = "m", Tolerance = 0.01,
                        Expected = path, Measured = length + FinalElongation(r),
                        Formula = "tangent + arc + tangent around radius R + r",
                    });
                    list.Add(new CheckResult
                    {
                        Quantity = "reported tension", Unit = "N", Tolerance = 0.03,
                        Expected = ea * FinalElongation(r) / length, Measured = MeanTension(r),
                        Formula = "E·A·strain of the same rope",
                    });
                    list.Add(new CheckResult
                    {
                        Quantity = "anchor force", Unit = "N", Tolerance = 0.03,
                        Expected = ea * FinalElongation(r) / length, Measured = 0.5 * (Norm(r.StartPinForce) + Norm(r.EndPinForce)),
                        Formula = "E·A·strain (frictionless bar: the tension reaches both anchors)",
                    });
                    break;
                }
            }
            return list;
        }

        /// <summary>
        /// A uniform rope released from a fixed start and swinging under viscous drag c (N·s/m²): every mode decays as
        /// exp(−c·t/(2μ)) (the drag per unit mass c/μ is the same everywhere). The decay rate of the centre of mass's swing (the
        /// least-squares slope of ln|peak| over its peaks) against c/(2μ) (2 %), and the time after which no particle is 1 cm
        /// or more from the vertical through the start against (2μ/c)·ln(A₀/1 cm), A₀ the farthest particle at release (5 %).
        /// </summary>
        static void AddSettleChecks(RunResult r, List<CheckResult> list)
        {
            var s = r.Scenario;
            double mu = s.Rope.ResolvedLinearDensity, c = s.Drag.ViscousDrag, rate = c / (2 * mu);
            list.Add(new CheckResult
            {
                Quantity = "swing decay rate", Unit = "1/s", Tolerance = 0.02, Expected = rate,
                Measured = r.SwingSeries == null ? double.NaN : DecayRate(r.SwingSeries, r.HostStep), Formula = "c/(2μ): amplitude ∝ exp(−c·t/(2μ))",
            });
            double a0 = ReleaseReach(s), settled = double.NaN;
            if (r.OffVerticalSeries != null && r.OffVerticalSeries.Length > 0 && r.OffVerticalSeries[r.OffVerticalSeries.Length - 1] < SettleDistance)
            {
                settled = 0;
                for (int k = 0; k < r.OffVerticalSeries.Length; k++)
                    if (r.OffVerticalSeries[k] >= SettleDistance) settled = (k + 1) * r.HostStep;
            }
            list.Add(new CheckResult
            {
                Quantity = "settled within 1 cm of the vertical at", Unit = "s", Tolerance = 0.05, Measured = settled,
                Expected = Math.Log(a0 / SettleDistance) / rate, Formula = "(2μ/c)·ln(A₀/1 cm), A₀ = " + JsonFields.Format(a0) + " m at release",
            });
        }

        /// <summary>How close to the vertical (m) a settled swing stays.</summary>
        public const double SettleDistance = 0.01;

        /// <summary>The farthest horizontal distance (m) of a particle from the vertical through the start in the scenario's initial shape.</summary>
        static double ReleaseReach(Scenario s)
        {
            var down = ScenarioGeometry.DownDirection(s.Gravity);
            var start = ScenarioGeometry.StartPosition(s);
            var positions = new Float3[s.Rope.Segments + 1];
            ScenarioGeometry.InitialPositions(s, positions);
            double farthest = 0;
            foreach (var p in positions)
            {
                var d = p - start;
                farthest = Math.Max(farthest, (d - down * Float3.Dot(d, down)).Length);
            }
            return farthest;
        }

        /// <summary>
        /// −(least-squares slope of ln|x| over the local maxima of |x|) in 1/s, samples <paramref name="dt"/> s apart (index k at
        /// (k + 1)·dt), over the maxima above 1e-4 of the largest (below, float32 positions round the swing); NaN with fewer than 3.
        /// </summary>
        public static double DecayRate(double[] x, double dt)
        {
            double st = 0, sy = 0, stt = 0, sty = 0, largest = 0;
            foreach (double v in x) largest = Math.Max(largest, Math.Abs(v));
            int peaks = 0;
            for (int k = 1; k + 1 < x.Length; k++)
            {
                double a = Math.Abs(x[k]);
                if (!(a > Math.Abs(x[k - 1]) && a >= Math.Abs(x[k + 1]) && a > 1e-4 * largest)) continue;
                double t = (k + 1) * dt, y = Math.Log(a);
                st += t; sy += y; stt += t * t; sty += t * y;
                peaks++;
            }
            return peaks < 3 ? double.NaN : -(peaks * sty - st * sy) / (peaks * stt - st * st);
        }

        /// <summary>Periods between the first and the last whole period a run of <paramref name="duration"/> s holds (the analytic period), at least 1.</summary>
        public static int AmplitudePeriods(double duration, double period) => Math.Max(1, (int)Math.Floor(duration / period + 1e-9) - 1);

        /// <summary>
        /// Undamped spring–mass released at rest unstretched: the amplitude of the last whole period against the first
        /// (window fits over the measured period, <see cref="DissipationMeasures.WindowAmplitude"/>), the first against the
        /// static elongation it swings about, and the largest substep anchor tension of the first period against 2·M·g.
        /// </summary>
        static void AddAmplitudeChecks(RunResult r, List<CheckResult> list, double load, double ropeMass, double g, double length, double ea)
        {
            double analytic = HeavyRopePeriod(load, ropeMass, length, ea);
            int periods = AmplitudePeriods(r.Scenario.Duration, analytic);
            double period = Period(r.LoadDrop, r.HostStep);
            double first = DissipationMeasures.WindowAmplitude(r.LoadDrop, r.HostStep, 0, period);
            double last = DissipationMeasures.WindowAmplitude(r.LoadDrop, r.HostStep, periods * period, period);
            list.Add(new CheckResult
            {
                Quantity = $"amplitude after {periods} periods", Unit = "m", Tolerance = 0.005, Expected = first, Measured = last,
                Formula = $"= the first period's (undamped; window fits over the measured period {period:G5} s)",
            });
            list.Add(new CheckResult
            {
                Quantity = "amplitude of the first period", Unit = "m", Tolerance = 0.01, Measured = first,
                Expected = StaticElongation(load, ropeMass, g, length, ea), Formula = "released unstretched: (M + m/2)·g·L/(E·A)",
            });
            double peak = 0;
            for (int k = 0; k < r.Steps && (k + 1) * r.HostStep <= analytic; k++) peak = Math.Max(peak, r.PeakTopTensionSeries[k]);
            list.Add(new CheckResult
            {
                Quantity = "peak anchor force, first period (substep max)", Unit = "N", Tolerance = 0.005, Measured = r.Steps > 0 ? peak : double.NaN,
                Expected = 2 * load * g, Formula = "2·M·g (rope mass neglected)",
            });
        }

        /// <summary>
        /// Load thrown down at v from the taut, unstretched position of a tension-only cord: the first three rebounds
        /// against v²/2g above that position (the worst first) and the bounce periods (apex to apex; the first from the
        /// virtual apex v/g before the start) against contact + flight.
        /// </summary>
        static void AddReboundChecks(RunResult r, List<CheckResult> list, double load, double g, double stiffness)
        {
            const int Bounces = 3;
            var s = r.Scenario;
            var down = ScenarioGeometry.DownDirection(s.Gravity);
            double v = Float3.Dot(s.End.Velocity, down);
            double height = v * v / (2 * g);
            double period = DissipationMeasures.ContactTime(load, stiffness, g, v) + 2 * v / g;
            var apexes = DissipationMeasures.Apexes(r.LoadDrop, r.HostStep, Bounces);
            var heights = new List<CheckResult>();
            var periods = new List<CheckResult>();
            double previous = -v / g;
            for (int b = 0; b < Bounces; b++)
            {
                bool found = b < apexes.Count;
                heights.Add(new CheckResult
                {
                    Quantity = $"rebound height, bounce {b + 1}", Unit = "m", Tolerance = 0.02, Expected = height,
                    // a bounce that never rises above the taut position within the run rebounded 0 m (100 % low)
                    Measured = found ? apexes[b].Height : r.NonFinite || r.Steps == 0 ? double.NaN : 0.0, Formula = found ? "v²/2g" : "v²/2g (no rebound above the taut position in the run)",
                });
                periods.Add(new CheckResult
                {
                    Quantity = $"bounce period, bounce {b + 1}", Unit = "s", Tolerance = 0.01, Expected = period,
                    Measured = found ? apexes[b].Time - previous : double.NaN,
                    Formula = "(π + 2·asin(x_s/A))/ω + 2v/g, ω² = k/M, x_s = Mg/k, A² = x_s² + v²/ω²",
                });
                if (found) previous = apexes[b].Time;
            }
            var worst = heights[0];
            foreach (var c in heights) if (!double.IsFinite(c.Measured) || (double.IsFinite(worst.Measured) && c.Error > worst.Error)) worst = c;
            list.Add(new CheckResult
            {
                Quantity = $"rebound height, worst of bounces 1–{Bounces}", Unit = "m", Tolerance = 0.02, Expected = height,
                Measured = worst.Measured, Formula = worst.Formula,
            });
            list.AddRange(heights);
            list.AddRange(periods);
        }

        /// <summary>
        /// A load hanging slack below a stiff rope snatches it: the largest substep anchor tension, and the largest at the
        /// host-step ends, against the massless formula Mg + sqrt((Mg)² + 2Mgkh) (h: the initial slack, rest length minus
        /// the distance between the ends), and, when the energy was tracked, its largest rise (none allowed beyond round-off).
        /// </summary>
        static void AddSnatchChecks(RunResult r, List<CheckResult> list, double load, double g, double stiffness)
        {
            var s = r.Scenario;
            double slack = Math.Max(0, s.Rope.RestLength - (ScenarioGeometry.EndPosition(s) - ScenarioGeometry.StartPosition(s)).Length);
            double expected = FallArrestForce(load, g, stiffness, slack);
            double peak = r.Steps > 0 ? 0 : double.NaN;
            for (int k = 0; k < r.Steps; k++) peak = Math.Max(peak, r.PeakTopTensionSeries[k]);
            const string Formula = "Mg + sqrt((Mg)² + 2Mgkh), k = E·A/L, h = slack";
            list.Add(new CheckResult { Quantity = "peak anchor force (substep max)", Unit = "N", Tolerance = 0.02, Expected = expected, Measured = peak, Formula = Formula });
            list.Add(new CheckResult { Quantity = "peak anchor force (host-step ends)", Unit = "N", Tolerance = 0.02, Expected = expected, Measured = r.PeakTopForce, Formula = Formula });
            if (r.EnergyTracked)
                list.Add(new CheckResult
                {
                    Quantity = "largest rise of the total energy", Unit = "J", Absolute = true, Expected = 0,
                    Tolerance = 1e-6 * Math.Abs(r.InitialEnergy), Measured = Math.Max(0, r.MaxEnergy - r.InitialEnergy),
                    Formula = "energy never rises (1e-6 of |E₀|)",
                });
        }

        /// <summary>
        /// Deployment x_d (m) of an energy absorber of plateau <paramref name="plateau"/> (N) in series with a massless lanyard of
        /// stiffness <paramref name="stiffness"/> (N/m) arresting <paramref name="mass"/> (kg) after a free fall of
        /// <paramref name="fallHeight"/> (m): M·g·(h + x_e + x_d) = F_p·x_d + F_p²/(2k), x_e = F_p/k.
        /// </summary>
        public static double AbsorberDeployment(double mass, double g, double stiffness, double fallHeight, double plateau)
        {
            double w = mass * g;
            return (w * (fallHeight + plateau / stiffness) - plateau * plateau / (2 * stiffness)) / (plateau - w);
        }

        /// <summary>
        /// A fall arrested by an energy absorber (issue 15): the largest substep force on the load against the plateau, the
        /// deployment against the energy balance (while it fits in the absorber's length), the plastic work against F_p·x_d,
        /// and the EN 355 verdict (≤ 6 kN).
        /// </summary>
        static void AddAbsorberChecks(RunResult r, List<CheckResult> list, double load, double g, double stiffness)
        {
            var rope = r.Scenario.Rope;
            double h = r.Scenario.Initial.FallHeight ?? rope.RestLength;
            double deployment = AbsorberDeployment(load, g, stiffness, h, rope.AbsorberForce);
            list.Add(new CheckResult
            {
                Quantity = "peak force on the load (substep max)", Unit = "N", Tolerance = 0.02, Measured = r.PeakLoadForce,
                Expected = rope.AbsorberForce, Formula = "the absorber's plateau F_p",
            });
            list.Add(new CheckResult
            {
                Quantity = "absorber deployment", Unit = "m", Tolerance = 0.02, Measured = r.AbsorberDeployment,
                Expected = Math.Min(deployment, rope.AbsorberDeployment),
                Formula = deployment <= rope.AbsorberDeployment ? "M·g·(h + x_e + x_d) = F_p·x_d + F_p²/(2k), x_e = F_p/k" : "used up: its deployment length",
            });
            list.Add(new CheckResult
            {
                Quantity = "plastic work", Unit = "J", Tolerance = 0.005, Measured = r.PlasticWork,
                Expected = rope.AbsorberForce * r.AbsorberDeployment, Formula = "F_p·x_d (the plateau's work)",
            });
            list.Add(new CheckResult
            {
                Quantity = "peak force over EN 355's 6 kN", Unit = "N", Absolute = true, Tolerance = 0, Expected = 0,
                Measured = Math.Max(0, r.PeakLoadForce - HookeRope.FallArrestLimits.En355), Formula = "EN 355: at most 6 kN with 100 kg",
            });
        }

        /// <summary>
        /// A plastic rope pulled slowly to its break (issue 15): the peak force against the neck onset F_n of the quasi-static
        /// curve and the elongation there, the largest departure of the sampled force from that curve up to the peak, and the
        /// force left when it broke (the neck softens the rope's force away before the break).
        /// </summary>
        static void AddPlasticChecks(RunResult r, List<CheckResult> list)
        {
            var curve = HookeRope.Solver.ForceElongationCurve.Of(ScenarioRunner.Settings(r.Scenario), 1.0);
            int peak = 0;
            for (int i = 1; i < r.Samples.Count; i++) if (r.Samples[i].TopTension > r.Samples[peak].TopTension) peak = i;
            double onsetForce = curve.PeakForce, onsetElongation = double.NaN, worst = 0;
            for (int i = 0; i < curve.Count; i++) if (curve.Force[i] == onsetForce) { onsetElongation = curve.Elongation[i]; break; }
            for (int i = 0; i <= peak && i < r.Samples.Count; i++)
                worst = Math.Max(worst, Math.Abs(r.Samples[i].TopTension - curve.ForceAt(r.Samples[i].Elongation)));
            bool any = r.Samples.Count > 0;
            list.Add(new CheckResult
            {
                Quantity = "peak force (neck onset)", Unit = "N", Tolerance = 0.01, Measured = any ? r.Samples[peak].TopTension : double.NaN,
                Expected = onsetForce, Formula = "F_n = E·A·ε_y + H·ε_pn, ε_pn = (ε_n − ε_y)/(1 + H/(E·A))",
            });
            list.Add(new CheckResult
            {
                Quantity = "elongation at the peak", Unit = "m", Tolerance = 0.02, Measured = any ? r.Samples[peak].Elongation : double.NaN,
                Expected = onsetElongation, Formula = "ε_n·L (the necking strain)",
            });
            list.Add(new CheckResult
            {
                Quantity = "largest force off the quasi-static curve before the peak", Unit = "N", Absolute = true, Tolerance = 0.01 * onsetForce,
                Expected = 0, Measured = any ? worst : double.NaN, Formula = "elastic, then hardening at H (1 % of F_n)",
            });
            list.Add(new CheckResult
            {
                Quantity = "tension when it broke", Unit = "N", Absolute = true, Tolerance = 0.1 * onsetForce, Expected = 0,
                Measured = double.IsNaN(r.BreakTime) ? double.NaN : r.BreakTension, Formula = "the neck softened the force (< 10 % of F_n)",
            });
        }

        /// <summary>Number of trailing samples spanning a whole number of periods, at most <paramref name="limit"/>.</summary>
        static int WholePeriods(RunResult r, double period, int limit)
        {
            int n = Math.Min(r.ElongationSeries.Length, Math.Max(limit, 1));
            double periods = Math.Floor(n * r.HostStep / period);
            if (periods < 1 || !double.IsFinite(periods)) return n;
            return Math.Min(n, (int)Math.Round(periods * period / r.HostStep));
        }

        /// <summary>Final length of the intact rope minus its rest length, m.</summary>
        public static double FinalElongation(RunResult r) =>
            r.ElongationSeries.Length > 0 ? r.ElongationSeries[r.ElongationSeries.Length - 1] : 0;

        static double MeanTension(RunResult r)
        {
            double sum = 0;
            foreach (var t in r.FinalTensions) sum += t;
            return sum / r.FinalTensions.Length;
        }

        /// <summary>
        /// Length (m) of the shortest path from the final start anchor to the final end anchor around the
        /// first collider (sphere or capsule cross-section, radius + rope radius): tangent, arc, tangent.
        /// </summary>
        public static double WrappedPathLength(Scenario s)
        {
            var a = s.Start.PositionAt(s.Duration);
            var b = s.End.PositionAt(s.Duration);
            var c = s.Colliders[0].Kind == ColliderKind.Capsule
                ? Float3.Lerp(s.Colliders[0].Center, s.Colliders[0].PointB, 0.5f)
                : s.Colliders[0].Center;
            double radius = s.Colliders[0].Radius + s.Rope.Radius;
            var ex = (b - a).NormalizedOr(new Float3(1f, 0f, 0f));
            var up = -ScenarioGeometry.DownDirection(s.Gravity);
            var ey = (up - ex * Float3.Dot(up, ex)).NormalizedOr(new Float3(0f, 1f, 0f));
            double ax = Float3.Dot(a - c, ex), ay = Float3.Dot(a - c, ey);
            double bx = Float3.Dot(b - c, ex), by = Float3.Dot(b - c, ey);
            double da = Math.Sqrt(ax * ax + ay * ay), db = Math.Sqrt(bx * bx + by * by);
            double tangentA = Math.Acos(radius / da), tangentB = Math.Acos(radius / db);
            double angleA = Math.Atan2(ay, ax);               // A on the left: measure its angle in [0, 2π)
            if (angleA < 0) angleA += 2 * Math.PI;
            angleA -= tangentA;                                // upper tangent point seen from A
            double angleB = Math.Atan2(by, bx) + tangentB;
            double arc = angleA - angleB;
            if (arc <= 0) return Math.Sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
            return Math.Sqrt(da * da - radius * radius) + Math.Sqrt(db * db - radius * radius) + radius * arc;
        }

        static double Norm(double[] v) => Math.Sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);

        static double Horizontal(double[] force, Scenario s)
        {
            var down = ScenarioGeometry.DownDirection(s.Gravity);
            double along = force[0] * down.X + force[1] * down.Y + force[2] * down.Z;
            double total = Norm(force);
            return Math.Sqrt(Math.Max(0, total * total - along * along));
        }

        static double Sag(RunResult r)
        {
            var down = ScenarioGeometry.DownDirection(r.Scenario.Gravity);
            var start = ScenarioGeometry.StartPosition(r.Scenario);
            double sag = 0;
            var p = r.FinalPositions;
            for (int i = 0; i < p.Length / 3; i++)
            {
                double d = (p[3 * i] - start.X) * down.X + (p[3 * i + 1] - start.Y) * down.Y + (p[3 * i + 2] - start.Z) * down.Z;
                if (d > sag) sag = d;
            }
            return sag;
        }

        static double MidRadius(RunResult r)
        {
            if (r.Profiles.Count == 0) return double.NaN;
            var radius = r.Profiles[r.Profiles.Count - 1].Radius;
            return radius[radius.Length / 2];
        }

        static double ThinnestFraction(RunResult r)
        {
            if (r.Profiles.Count == 0) return double.NaN;
            var p = r.Profiles[r.Profiles.Count - 1];
            int best = 0;
            for (int i = 1; i < p.Radius.Length; i++) if (p.Radius[i] < p.Radius[best]) best = i;
            return p.Arc[best] / r.Scenario.Rope.RestLength;
        }

        /// <summary>Particle radius at the end of the rope farthest from the defect (last profile), m.</summary>
        static double FarRadius(RunResult r)
        {
            if (r.Profiles.Count == 0) return double.NaN;
            var radius = r.Profiles[r.Profiles.Count - 1].Radius;
            double defect = r.Scenario.Rope.DefectPosition;
            int i = defect < 0.5 ? (int)(radius.Length * 0.9) : (int)(radius.Length * 0.1);
            return radius[i];
        }

        static double LastNeckRadius(RunResult r) => r.Samples.Count > 0 ? r.Samples[r.Samples.Count - 1].NeckRadius : double.NaN;

        static double Penetration(RunResult r)
        {
            double deepest = double.NegativeInfinity;
            var p = r.FinalPositions;
            foreach (var c in r.Scenario.Colliders)
            {
                for (int i = 0; i < p.Length / 3; i++)
                {
                    double particleRadius = r.FinalRadii != null ? r.FinalRadii[i] : r.Scenario.Rope.Radius;
                    double depth = c.Kind switch
                    {
                        ColliderKind.Sphere => c.Radius + particleRadius - Distance(p, i, c.Center.X, c.Center.Y, c.Center.Z),
                        ColliderKind.Capsule => c.Radius + particleRadius - SegmentDistance(p, i, c),
                        ColliderKind.Plane => -(((p[3 * i] - c.Center.X) * c.Normal.X + (p[3 * i + 1] - c.Center.Y) * c.Normal.Y + (p[3 * i + 2] - c.Center.Z) * c.Normal.Z) - particleRadius),
                        _ => double.NegativeInfinity,
                    };
                    if (depth > deepest) deepest = depth;
                }
            }
            return deepest;
        }

        /// <summary>Smallest final collision radius in m (the rest radius when none was recorded).</summary>
        static double SmallestRadius(RunResult r)
        {
            if (r.FinalRadii == null || r.FinalRadii.Length == 0) return r.Scenario.Rope.Radius;
            double min = double.PositiveInfinity;
            foreach (var v in r.FinalRadii) min = Math.Min(min, v);
            return min;
        }

        static double Distance(double[] p, int i, double x, double y, double z)
        {
            double dx = p[3 * i] - x, dy = p[3 * i + 1] - y, dz = p[3 * i + 2] - z;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        static double SegmentDistance(double[] p, int i, ColliderSpec c)
        {
            double ax = c.Center.X, ay = c.Center.Y, az = c.Center.Z;
            double bx = c.PointB.X - ax, by = c.PointB.Y - ay, bz = c.PointB.Z - az;
            double px = p[3 * i] - ax, py = p[3 * i + 1] - ay, pz = p[3 * i + 2] - az;
            double len2 = bx * bx + by * by + bz * bz;
            double t = len2 > 0 ? Math.Clamp((px * bx + py * by + pz * bz) / len2, 0, 1) : 0;
            return Distance(p, i, ax + t * bx, ay + t * by, az + t * bz);
        }
    }
}
