using System;
using System.Diagnostics;
using HookeRope.Lab.Scenarios;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope.Lab.Simulation
{
    /// <summary>What a run records besides the headline numbers.</summary>
    public sealed class RunOptions
    {
        /// <summary>Record CSV samples at outputs.sampleRate.</summary>
        public bool RecordSamples = true;
        /// <summary>Evaluate the total energy every step (O(n) per step).</summary>
        public bool TrackEnergy = true;
        /// <summary>Capture radius profiles and meshes at the scenario's instants.</summary>
        public bool Captures = true;
        /// <summary>Run the radius model (Poisson thinning, neck, neck break) after every step.</summary>
        public bool Radius = true;
        /// <summary>Called after every host step with the step index (progress bars).</summary>
        public Action<int> Progress;

        /// <summary>Options for timing runs: only the headline numbers.</summary>
        public static RunOptions Lean() => new RunOptions { RecordSamples = false, TrackEnergy = false, Captures = false };
    }

    /// <summary>Builds a <see cref="Rope"/> from a <see cref="Scenario"/> and steps it through the scenario.</summary>
    public static class ScenarioRunner
    {
        /// <summary>Solver settings for a scenario (SI units).</summary>
        public static RopeSettings Settings(Scenario s)
        {
            var r = s.Rope;
            var settings = new RopeSettings();
            settings.RestLength = (float)r.RestLength;
            settings.SegmentCount = r.Segments;
            settings.Radius = (float)r.Radius;
            if (r.AxialStiffness.HasValue) settings.AxialStiffness = (float)r.AxialStiffness.Value;
            else settings.YoungsModulus = (float)(r.YoungsModulus ?? RopeSpec.DefaultYoungsModulus);
            if (r.LinearDensity.HasValue) settings.LinearDensity = (float)r.LinearDensity.Value;
            else settings.Density = (float)(r.Density ?? RopeSpec.DefaultDensity);
            settings.Damping = (float)s.Solver.Damping;
            settings.Gravity = s.Gravity;
            settings.Substeps = s.Solver.Substeps;
            settings.Iterations = s.Solver.Iterations;
            settings.Solver = s.Solver.Method == SolverMethod.GaussSeidel ? ConstraintSolverKind.GaussSeidel : ConstraintSolverKind.ExactChain;
            settings.Tension = s.Solver.TensionOnly ? TensionModel.TensionOnly : TensionModel.Bilateral;
            settings.Integrator = s.Solver.Integrator;
            settings.YieldStrain = (float)r.YieldStrain;
            settings.HardeningModulus = (float)r.HardeningModulus;
            settings.NeckingStrain = (float)r.NeckingStrain;
            settings.UltimateStrain = (float)r.UltimateStrain;
            if (r.IsPlastic) settings.SetPlasticity((float)r.YieldStrain, (float)r.HardeningModulus, (float)r.NeckingStrain, (float)r.UltimateStrain);
            settings.AbsorberForce = (float)r.AbsorberForce;
            settings.AbsorberDeployment = (float)r.AbsorberDeployment;
            settings.EnergyAbsorber = r.EnergyAbsorber;
            settings.ViscousDrag = (float)s.Drag.ViscousDrag;
            settings.DragCoefficient = (float)s.Drag.DragCoefficient;
            settings.SkinFriction = (float)s.Drag.SkinFriction;
            settings.AirDensity = (float)s.Drag.AirDensity;
            settings.Wind = s.Drag.Wind;
            return settings;
        }

        /// <summary>The rope of a scenario in its initial state, with pins, loads and colliders.</summary>
        public static RopeSetup Build(Scenario s, bool withRadius = true)
        {
            var rope = new Rope(Settings(s), ScenarioGeometry.StartPosition(s), ScenarioGeometry.EndPosition(s));
            var positions = new Float3[rope.ParticleCount];
            ScenarioGeometry.InitialPositions(s, positions);
            for (int i = 0; i < positions.Length; i++) rope.SetPosition(i, positions[i]);
            var setup = new RopeSetup { Rope = rope };
            setup.StartPin = Attach(rope, s.Start, 0, positions[0], out setup.StartLoad);
            setup.EndPin = Attach(rope, s.End, rope.ParticleCount - 1, positions[positions.Length - 1], out setup.EndLoad);
            foreach (var c in s.Colliders) rope.AddCollider(Shape(c));
            var mesh = new TubeMeshSettings { RadialSegments = s.Rope.RadialSegments, RingTolerance = (float)s.Rope.RingTolerance };
            mesh.Burr.Seed = (uint)s.Rope.Seed;
            setup.Simulation = new RopeSimulation(rope, withRadius ? RadiusSettings(s) : null, mesh);
            return setup;
        }

        /// <summary>Radius-model settings of a scenario: Poisson thinning, neck (mode, onset, defect) and fracture at the defect.</summary>
        public static RadiusSettings RadiusSettings(Scenario s)
        {
            var r = s.Rope;
            var settings = new RadiusSettings();
            settings.PoissonThinning = r.PoissonThinning;
            settings.PoissonRatio = (float)r.PoissonRatio;
            settings.NeckMode = r.NeckMode == "paper" ? NeckMode.Paper : NeckMode.Zone;
            settings.Necking = r.Necking;
            settings.NeckRadiusFraction = (float)r.NeckRadiusFraction;
            settings.DefectPosition = (float)r.DefectPosition;
            settings.Fracture = r.Fracture;
            settings.BreakStrain = (float)r.BreakStrain;
            settings.BreakRadiusFraction = (float)r.BreakRadiusFraction;
            settings.NeckZoneDiameters = (float)r.NeckZoneDiameters;
            settings.NeckGrowthStrain = (float)r.NeckGrowthStrain;
            settings.SlackKeepsRestRadius = r.SlackKeepsRestRadius;
            return settings;
        }

        static int Attach(Rope rope, AttachmentSpec a, int particle, Float3 position, out int load)
        {
            load = -1;
            switch (a.Kind)
            {
                case AttachmentKind.Fixed:
                case AttachmentKind.Keyframes:
                    return rope.AddPin(particle, position, (float)a.Compliance);
                case AttachmentKind.Body:
                    load = rope.AddLoad(particle, (float)a.Mass);
                    rope.SetVelocity(particle, a.Velocity);
                    return -1;
                default:
                    return -1;
            }
        }

        /// <summary>Solver collider for a scenario collider.</summary>
        public static ColliderShape Shape(ColliderSpec c)
        {
            float friction = (float)c.Friction;
            switch (c.Kind)
            {
                case Scenarios.ColliderKind.Plane:
                    return ColliderShape.Plane(c.Center, c.Normal, friction);
                case Scenarios.ColliderKind.Sphere:
                    return ColliderShape.Sphere(c.Center, (float)c.Radius, friction);
                case Scenarios.ColliderKind.Capsule:
                    var axis = c.PointB - c.Center;
                    var rotation = axis.Length > 1e-6f ? Quat.FromToRotation(new Float3(0f, 1f, 0f), axis) : Quat.Identity;
                    return ColliderShape.Capsule(Float3.Lerp(c.Center, c.PointB, 0.5f), rotation, (float)c.Radius, axis.Length / 2, friction);
                default:
                    return ColliderShape.Box(c.Center, EulerToQuat(c.EulerDegrees), c.HalfExtents, friction);
            }
        }

        /// <summary>Unity's Euler convention (degrees; rotate about Z, then X, then Y).</summary>
        public static Quat EulerToQuat(Float3 degrees)
        {
            const float toRadians = MathF.PI / 180f;
            var qx = Quat.FromAxisAngle(new Float3(1f, 0f, 0f), degrees.X * toRadians);
            var qy = Quat.FromAxisAngle(new Float3(0f, 1f, 0f), degrees.Y * toRadians);
            var qz = Quat.FromAxisAngle(new Float3(0f, 0f, 1f), degrees.Z * toRadians);
            return qy * qx * qz;
        }

        /// <summary>Runs a scenario to its duration and returns what it produced.</summary>
        public static RunResult Run(Scenario s, RunOptions options = null)
        {
            options = options ?? new RunOptions();
            var setup = Build(s, options.Radius);
            var rope = setup.Rope;
            var result = new RunResult { Scenario = s };
            int last = rope.ParticleCount - 1;
            double weight = s.End.LoadMass * s.Gravity.Length;
            var down = ScenarioGeometry.DownDirection(s.Gravity);
            var releasePosition = rope.GetPosition(last);
            double lowest = 0, tautDrop = double.NaN;
            var readouts = setup.Simulation.Readouts;
            if (setup.EndLoad >= 0) readouts.ArrestLoad = setup.EndLoad;
            var constructionBreak = readouts.FirstBreak;
            if (constructionBreak.HasValue)
            {
                // the radius model's fracture decision ran once while the rope was built (RopeSimulation's constructor)
                result.BrokenAtConstruction = true;
                result.BreakTime = 0;
                result.BreakTension = constructionBreak.Value.Tension;
            }
            result.InitialEnergy = options.TrackEnergy ? rope.TotalEnergy() : 0;
            result.EnergyTracked = options.TrackEnergy;
            result.MaxEnergy = result.InitialEnergy;
            double dt = s.HostStep;
            int steps = s.StepCount;
            result.HostStep = dt;
            result.LoadDrop = new double[steps];
            result.ElongationSeries = new double[steps];
            result.TopTensionSeries = new double[steps];
            result.PeakTopTensionSeries = new double[steps];
            result.ResidualSeries = new float[steps];
            bool swing = s.Expect.Check == "settle";
            var swingOrigin = ScenarioGeometry.StartPosition(s);
            Float3 swingAlong = default;
            if (swing)
            {
                result.SwingSeries = new double[steps];
                result.OffVerticalSeries = new double[steps];
                swingAlong = Swing(rope, swingOrigin, down, default, out _, out _);
            }
            double sampleInterval = s.Outputs.SampleRate > 0 ? 1.0 / s.Outputs.SampleRate : 0;
            double nextSample = 0;
            int nextProfile = 0, nextMesh = 0;
            var profileTimes = Sorted(s.Outputs.ProfileTimes);
            var meshTimes = Sorted(s.Outputs.GltfTimes);
            if (options.RecordSamples)
            {
                result.Samples.Add(Measure(setup, 0, options));
                nextSample = sampleInterval;
            }
            bool keyMoments = options.Captures && setup.Simulation.RadiusModel != null && (s.Rope.PoissonThinning || s.Rope.Necking);
            double onsetRadius = s.Rope.NeckRadiusFraction * s.Rope.Radius, deepest = s.Rope.Radius;
            RadiusProfile thinnest = null;
            bool onsetSeen = false, breakSeen = !double.IsNaN(result.BreakTime);
            var player = new EventPlayer(s, setup);
            result.Events = player.Applied;
            var substepTensions = new SubstepTensionWindow();
            var watch = Stopwatch.StartNew();
            for (int k = 0; k < steps; k++)
            {
                double t = (k + 1) * dt;
                player.BeforeStep(k * dt, dt);
                var report = setup.Step((float)dt);
                result.Steps = k + 1;
                if (report.Residual > result.MaxResidual) result.MaxResidual = report.Residual;
                result.ResidualSeries[k] = report.Residual;
                var load = rope.GetPosition(last);
                if (!load.IsFinite || !AllFinite(rope))
                {
                    result.NonFinite = true;
                    break;
                }
                double extent = (load - releasePosition).Length;
                if (extent > result.MaxExtent) result.MaxExtent = extent;
                double top = readouts.TopTension;
                double bottom = readouts.BottomTension;
                if (top > result.PeakTopForce) result.PeakTopForce = top;
                result.PeakLoadForce = readouts.PeakArrestForce;
                var firstBreak = readouts.FirstBreak;
                if (firstBreak.HasValue && double.IsNaN(result.BreakTime))
                {
                    result.BreakTime = firstBreak.Value.Time;
                    result.BreakTension = firstBreak.Value.Tension;
                }
                double elongation = readouts.Elongation;
                if (elongation > result.MaxElongation) result.MaxElongation = elongation;
                result.AbsorberDeployment = readouts.AbsorberDeployment;
                result.PlasticElongation = readouts.PlasticElongation;
                result.PlasticWork = readouts.PlasticWork;
                double drop = Float3.Dot(load - releasePosition, down);
                result.LoadDrop[k] = drop;
                result.ElongationSeries[k] = elongation;
                result.TopTensionSeries[k] = top;
                result.PeakTopTensionSeries[k] = rope.BrokenSegments[0] ? 0.0 : rope.PeakTensions[0];
                if (swing)
                {
                    Swing(rope, swingOrigin, down, swingAlong, out result.SwingSeries[k], out result.OffVerticalSeries[k]);
                }
                if (drop > lowest) lowest = drop;
                if (double.IsNaN(tautDrop) && bottom > Math.Max(0.1 * weight, 1e-6) && k > 0)
                {
                    tautDrop = drop;
                    result.TautTime = t;
                }
                if (keyMoments)
                {
                    double neck = readouts.NeckRadius;
                    if (!breakSeen && !double.IsNaN(result.BreakTime))
                    {
                        breakSeen = true;
                        result.KeyProfiles.Add(Labelled(Profile(setup, t), "break"));
                    }
                    if (s.Rope.Necking && !onsetSeen && neck < onsetRadius)
                    {
                        onsetSeen = true;
                        result.KeyProfiles.Add(Labelled(Profile(setup, t), "neck onset"));
                    }
                    if (!breakSeen && neck < deepest - 0.002 * s.Rope.Radius)
                    {
                        deepest = neck;   // a new deepest point, at most 500 captures over a run
                        thinnest = Labelled(Profile(setup, t), "thinnest (intact)");
                    }
                }
                if (options.TrackEnergy) RecordEnergy(rope, result, late: k >= steps / 2);
                options.Progress?.Invoke(k);
                if (options.RecordSamples) substepTensions.Add(rope);
                if (options.RecordSamples && t >= nextSample - 1e-9)
                {
                    result.Samples.Add(substepTensions.Complete(Measure(setup, t, options)));
                    nextSample += sampleInterval;
                    if (sampleInterval > 0 && nextSample < t) nextSample = t + sampleInterval;
                }
                if (options.Captures)
                {
                    while (nextProfile < profileTimes.Length && t >= profileTimes[nextProfile] - dt / 2)
                    {
                        result.Profiles.Add(Profile(setup, t));
                        nextProfile++;
                    }
                    while (nextMesh < meshTimes.Length && t >= meshTimes[nextMesh] - dt / 2)
                    {
                        var mesh = MeshCapture.Capture(setup, s, t);
                        if (mesh != null) result.Meshes.Add(mesh);
                        nextMesh++;
                    }
                }
            }
            result.WallSeconds = watch.Elapsed.TotalSeconds;
            if (thinnest != null) result.KeyProfiles.Add(thinnest);
            result.KeyProfiles.Sort((a, b) => a.Time.CompareTo(b.Time));
            if (result.Steps < steps)
            {
                Array.Resize(ref result.LoadDrop, result.Steps);
                Array.Resize(ref result.ElongationSeries, result.Steps);
                Array.Resize(ref result.TopTensionSeries, result.Steps);
                Array.Resize(ref result.PeakTopTensionSeries, result.Steps);
                Array.Resize(ref result.ResidualSeries, result.Steps);
                if (swing)
                {
                    Array.Resize(ref result.SwingSeries, result.Steps);
                    Array.Resize(ref result.OffVerticalSeries, result.Steps);
                }
            }
            result.TotalDrop = lowest;
            result.ArrestDistance = double.IsNaN(tautDrop) ? 0 : lowest - tautDrop;
            Final(setup, result);
            return result;
        }

        /// <summary>
        /// The swing of a rope hanging from <paramref name="origin"/> (m; <paramref name="down"/> the unit vector along gravity):
        /// the horizontal offset of its centre of mass, signed along <paramref name="along"/> (m), and the largest horizontal
        /// distance of a particle (m). Returns the unit direction of the centre of mass's horizontal offset (for the first call).
        /// </summary>
        static Float3 Swing(Rope rope, Float3 origin, Float3 down, Float3 along, out double offset, out double farthest)
        {
            double mass = 0, cx = 0, cy = 0, cz = 0;
            farthest = 0;
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                var r = rope.GetPosition(i) - origin;
                var horizontal = r - down * Float3.Dot(r, down);
                farthest = Math.Max(farthest, horizontal.Length);
                double m = rope.GetParticleMass(i);
                mass += m;
                cx += m * horizontal.X; cy += m * horizontal.Y; cz += m * horizontal.Z;
            }
            var centre = new Float3((float)(cx / mass), (float)(cy / mass), (float)(cz / mass));
            offset = Float3.Dot(centre, along);
            return centre.NormalizedOr(new Float3(1f, 0f, 0f));
        }

        /// <summary>Updates the energy maxima of <paramref name="result"/> (J) for the second half of the run when <paramref name="late"/>, else the first.</summary>
        static void RecordEnergy(Rope rope, RunResult result, bool late)
        {
            double motion = rope.KineticEnergy() + rope.GravitationalEnergy();  // the same sum as Rope.TotalEnergy, split
            double energy = motion + rope.ElasticEnergy();
            if (energy > result.MaxEnergy) result.MaxEnergy = energy;
            if (late)
            {
                if (energy > result.LateMaxEnergy) result.LateMaxEnergy = energy;
                if (motion > result.LateMaxMotionEnergy) result.LateMaxMotionEnergy = motion;
            }
            else
            {
                if (energy > result.EarlyMaxEnergy) result.EarlyMaxEnergy = energy;
                if (motion > result.EarlyMaxMotionEnergy) result.EarlyMaxMotionEnergy = motion;
            }
        }

        static double[] Sorted(System.Collections.Generic.List<double> times)
        {
            var a = times.ToArray();
            Array.Sort(a);
            return a;
        }

        static bool AllFinite(Rope rope)
        {
            var x = rope.PositionX;
            var y = rope.PositionY;
            var z = rope.PositionZ;
            for (int i = 0; i < x.Length; i++)
                if (!float.IsFinite(x[i]) || !float.IsFinite(y[i]) || !float.IsFinite(z[i])) return false;
            return true;
        }

        static Sample Measure(RopeSetup setup, double t, RunOptions options)
        {
            var rope = setup.Rope;
            var readouts = setup.Simulation.Readouts;
            int last = rope.ParticleCount - 1;
            var p = rope.GetPosition(last);
            var v = rope.GetVelocity(last);
            return new Sample
            {
                Time = t,
                X = p.X, Y = p.Y, Z = p.Z,
                VX = v.X, VY = v.Y, VZ = v.Z,
                TopTension = readouts.TopTension,
                BottomTension = readouts.BottomTension,
                Elongation = readouts.Elongation,
                MinRadius = readouts.MinRadius,
                NeckRadius = readouts.NeckRadius,
                Broken = readouts.IsBroken,
                Residual = readouts.Residual,
                Energy = options.TrackEnergy ? rope.TotalEnergy() : 0,
            };
        }

        static RadiusProfile Labelled(RadiusProfile profile, string label)
        {
            profile.Label = label;
            return profile;
        }

        static RadiusProfile Profile(RopeSetup setup, double t)
        {
            var rope = setup.Rope;
            var rest = rope.RestLengths;
            const int perSegment = 8;
            var model = setup.Simulation.RadiusModel;
            if (model == null)
            {
                var radius = rope.ParticleRadius;
                var plain = new RadiusProfile { Time = t, Arc = new double[radius.Length], Radius = new double[radius.Length] };
                double arc = 0;
                for (int i = 0; i < radius.Length; i++)
                {
                    plain.Arc[i] = arc;
                    plain.Radius[i] = radius[i];
                    if (i < rest.Length) arc += rest[i];
                }
                return plain;
            }
            int n = rope.SegmentCount;
            var profile = new RadiusProfile { Time = t, Arc = new double[n * perSegment + 1], Radius = new double[n * perSegment + 1] };
            double start = 0;
            for (int j = 0; j < n; j++)
            {
                for (int k = 0; k < perSegment; k++)
                {
                    float f = (float)k / perSegment;
                    profile.Arc[j * perSegment + k] = start + rest[j] * f;
                    profile.Radius[j * perSegment + k] = model.RadiusAt(j, f);
                }
                start += rest[j];
            }
            profile.Arc[n * perSegment] = start;
            profile.Radius[n * perSegment] = model.RadiusAt(n - 1, 1f);
            return profile;
        }

        static void Final(RopeSetup setup, RunResult result)
        {
            var rope = setup.Rope;
            result.FinalPositions = new double[rope.ParticleCount * 3];
            result.FinalRadii = new double[rope.ParticleCount];
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                var p = rope.GetPosition(i);
                result.FinalPositions[3 * i] = p.X;
                result.FinalPositions[3 * i + 1] = p.Y;
                result.FinalPositions[3 * i + 2] = p.Z;
                result.FinalRadii[i] = rope.ParticleRadius[i];
                result.FinalMaxSpeed = Math.Max(result.FinalMaxSpeed, rope.GetVelocity(i).Length);
            }
            result.FinalTensions = new double[rope.SegmentCount];
            for (int j = 0; j < rope.SegmentCount; j++) result.FinalTensions[j] = rope.Tensions[j];
            if (setup.StartPin >= 0) Copy(rope.GetPinForce(setup.StartPin), result.StartPinForce);
            if (setup.EndPin >= 0) Copy(rope.GetPinForce(setup.EndPin), result.EndPinForce);
            if (setup.StartLoad >= 0) Copy(rope.GetLoadForce(setup.StartLoad), result.StartLoadForce);
            if (setup.EndLoad >= 0) Copy(rope.GetLoadForce(setup.EndLoad), result.EndLoadForce);
        }

        static void Copy(Float3 f, double[] to)
        {
            to[0] = f.X;
            to[1] = f.Y;
            to[2] = f.Z;
        }
    }

    /// <summary>A rope built for a scenario and the handles of its attachments.</summary>
    public sealed class RopeSetup
    {
        /// <summary>The rope.</summary>
        public Rope Rope;
        /// <summary>Pin of particle 0, or −1.</summary>
        public int StartPin = -1;
        /// <summary>Pin of the last particle, or −1.</summary>
        public int EndPin = -1;
        /// <summary>Load on particle 0, or −1.</summary>
        public int StartLoad = -1;
        /// <summary>Load on the last particle, or −1.</summary>
        public int EndLoad = -1;
        /// <summary>The core facade: solver + radius model + tube mesh.</summary>
        public RopeSimulation Simulation;

        /// <summary>One host step of the facade (solver, then radii, neck break), s.</summary>
        public StepReport Step(float hostDeltaTime) => Simulation.Step(hostDeltaTime);

        /// <summary>The radius half of <see cref="Step"/> alone (used to measure its allocations).</summary>
        public void UpdateRadii() => Simulation.UpdateRadii();
    }
}
