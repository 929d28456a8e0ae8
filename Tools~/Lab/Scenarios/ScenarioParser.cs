using System;
using System.Collections.Generic;
using System.Text.Json;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Scenarios
{
    /// <summary>
    /// Reads a scenario from JSON with strict validation: unknown fields, wrong types, out-of-range
    /// values and oversized arrays throw a <see cref="ScenarioException"/> naming the JSON path.
    /// The accepted format is documented field by field in Documentation~/lab.md.
    /// </summary>
    public static class ScenarioParser
    {
        /// <summary>Largest accepted document in bytes.</summary>
        public const int MaxDocumentBytes = 4 * 1024 * 1024;
        /// <summary>Most colliders in one scenario.</summary>
        public const int MaxColliders = 64;
        /// <summary>Most keyframes of one moving anchor.</summary>
        public const int MaxKeyframes = 10000;
        /// <summary>Most instants in outputs.profileTimes / outputs.gltfTimes.</summary>
        public const int MaxInstants = 32;
        /// <summary>Most timed events in one scenario.</summary>
        public const int MaxEvents = 256;
        /// <summary>Most CSV rows one run may write.</summary>
        public const double MaxRows = 2e6;
        /// <summary>Most host steps one run may take.</summary>
        public const double MaxSteps = 2e7;

        /// <summary>Parses and validates a scenario document.</summary>
        public static Scenario Parse(string json)
        {
            if (json == null) throw new ScenarioException("$", "empty document");
            if (json.Length > MaxDocumentBytes)
                throw new ScenarioException("$", $"document too large ({json.Length} characters, at most {MaxDocumentBytes})");
            JsonDocument document;
            try
            {
                document = JsonDocument.Parse(json, new JsonDocumentOptions
                {
                    CommentHandling = JsonCommentHandling.Skip,
                    AllowTrailingCommas = false,
                    MaxDepth = 16,
                });
            }
            catch (JsonException e)
            {
                string where = e.LineNumber.HasValue
                    ? $" at line {e.LineNumber + 1}, column {e.BytePositionInLine + 1}"
                    : "";
                throw new ScenarioException("$", "not valid JSON" + where);
            }
            using (document)
            {
                return Read(new JsonFields(document.RootElement, "$"));
            }
        }

        static Scenario Read(JsonFields root)
        {
            var s = new Scenario();
            s.Name = root.String("name", s.Name, 64);
            foreach (char c in s.Name)
                if (!(char.IsLetterOrDigit(c) || c == '-' || c == '_'))
                    throw new ScenarioException("$.name", "use only letters, digits, '-' and '_' (it names output files)");
            if (s.Name.Length == 0) throw new ScenarioException("$.name", "must not be empty");
            s.Description = root.String("description", s.Description, 500);
            s.Gravity = root.Vector(RopeParameters.Gravity.Json, s.Gravity, RopeParameters.Gravity.Max);
            s.Duration = root.Number("duration", s.Duration, 0, 600, minExclusive: true);
            bool hasStep = root.Has("hostStep"), hasRate = root.Has("frameRate");
            if (hasStep && hasRate)
                throw new ScenarioException("$.frameRate", "give either hostStep or frameRate, not both");
            if (hasStep) s.HostStep = root.Number("hostStep", s.HostStep, 0, 0.1, minExclusive: true);
            if (hasRate) s.HostStep = 1.0 / root.Number("frameRate", 90, 10, 100000);
            if (s.Duration / s.HostStep > MaxSteps)
                throw new ScenarioException("$.duration", $"duration / hostStep exceeds {MaxSteps:G3} host steps");

            var solver = root.Object("solver");
            if (solver != null) ReadSolver(solver, s.Solver);
            var rope = root.Object("rope");
            if (rope != null) ReadRope(rope, s.Rope);
            var drag = root.Object("drag");
            if (drag != null) ReadDrag(drag, s.Drag);
            s.Start = ReadAttachment(root.Object("start"), s.Start);
            s.End = ReadAttachment(root.Object("end"), s.End);
            var initial = root.Object("initial");
            if (initial != null) ReadInitial(initial, s.Initial);
            var colliders = root.Array("colliders", MaxColliders);
            for (int i = 0; i < colliders.Count; i++)
                s.Colliders.Add(ReadCollider(new JsonFields(colliders[i], $"$.colliders[{i}]")));
            var events = root.Array("events", MaxEvents);
            for (int i = 0; i < events.Count; i++)
                s.Events.Add(ReadEvent(new JsonFields(events[i], $"$.events[{i}]"), s));
            s.Events = System.Linq.Enumerable.ToList(System.Linq.Enumerable.OrderBy(s.Events, e => e.Time));   // stable: ties keep file order
            var outputs = root.Object("outputs");
            if (outputs != null) ReadOutputs(outputs, s.Outputs, s.Duration);
            var expect = root.Object("expect");
            if (expect != null)
            {
                s.Expect.Check = expect.Choice("check", "none", "none", "fall-arrest", "static-hang", "period",
                    "catenary", "poisson", "neck", "fracture", "collision", "amplitude", "rebound", "snatch", "absorber", "plastic", "settle");
                expect.RejectUnknown();
            }
            root.RejectUnknown();
            CrossCheck(s);
            return s;
        }

        static void ReadSolver(JsonFields f, SolverSpec spec)
        {
            spec.Method = f.Choice(RopeParameters.Solver.Json, spec.Method == SolverMethod.GaussSeidel ? "gauss-seidel" : "exact-chain",
                "gauss-seidel", "exact-chain") == "gauss-seidel" ? SolverMethod.GaussSeidel : SolverMethod.ExactChain;
            spec.Substeps = f.Parameter(RopeParameters.Substeps.Row, spec.Substeps);
            spec.Iterations = f.Parameter(RopeParameters.Iterations.Row, spec.Iterations);
            spec.Damping = f.Parameter(RopeParameters.Damping.Row, spec.Damping);
            spec.TensionOnly = f.Choice(RopeParameters.TensionModel.Json, spec.TensionOnly ? "tension-only" : "bilateral",
                "tension-only", "bilateral") == "tension-only";
            spec.Integrator = f.Choice(RopeParameters.Integrator.Json, SolverSpec.IntegratorJson(spec.Integrator),
                "backward-euler", "bdf2") == "bdf2" ? HookeRope.Solver.TimeIntegrator.Bdf2 : HookeRope.Solver.TimeIntegrator.BackwardEuler;
            f.RejectUnknown();
        }

        static void ReadRope(JsonFields f, RopeSpec r)
        {
            r.RestLength = f.Parameter(RopeParameters.RestLength.Row, r.RestLength);
            r.Segments = f.Parameter(RopeParameters.SegmentCount.Row, r.Segments);
            r.Radius = f.Parameter(RopeParameters.Radius.Row, r.Radius);
            r.YoungsModulus = f.OptionalParameter(RopeParameters.YoungsModulus.Row);
            r.AxialStiffness = f.OptionalParameter(RopeParameters.AxialStiffness.Row);
            if (r.YoungsModulus.HasValue && r.AxialStiffness.HasValue)
                throw new ScenarioException(f.Child(RopeParameters.AxialStiffness.Json), "give either youngsModulus or axialStiffness, not both");
            r.LinearDensity = f.OptionalParameter(RopeParameters.LinearDensity.Row);
            r.Density = f.OptionalParameter(RopeParameters.Density.Row);
            if (r.LinearDensity.HasValue && r.Density.HasValue)
                throw new ScenarioException(f.Child(RopeParameters.Density.Json), "give either linearDensity or density, not both");
            r.PoissonThinning = f.Parameter(RopeParameters.PoissonThinning.Row, r.PoissonThinning);
            r.PoissonRatio = f.Parameter(RopeParameters.PoissonRatio.Row, r.PoissonRatio);
            r.Necking = f.Parameter(RopeParameters.Necking.Row, r.Necking);
            r.NeckMode = f.Choice(RopeParameters.NeckMode.Json, r.NeckMode, "zone", "paper");
            r.NeckRadiusFraction = f.Parameter(RopeParameters.NeckRadiusFraction.Row, r.NeckRadiusFraction);
            r.DefectPosition = f.Parameter(RopeParameters.DefectPosition.Row, r.DefectPosition);
            r.Fracture = f.Parameter(RopeParameters.Fracture.Row, r.Fracture);
            r.BreakStrain = f.Parameter(RopeParameters.BreakStrain.Row, r.BreakStrain);
            r.BreakRadiusFraction = f.Parameter(RopeParameters.BreakRadiusFraction.Row, r.BreakRadiusFraction);
            r.NeckZoneDiameters = f.Parameter(RopeParameters.NeckZoneDiameters.Row, r.NeckZoneDiameters);
            r.NeckGrowthStrain = f.Parameter(RopeParameters.NeckGrowthStrain.Row, r.NeckGrowthStrain);
            r.SlackKeepsRestRadius = f.Parameter(RopeParameters.SlackKeepsRestRadius.Row, r.SlackKeepsRestRadius);
            r.RadialSegments = f.Parameter(RopeParameters.RadialSegments.Row, r.RadialSegments);
            r.RingTolerance = f.Parameter(RopeParameters.RingTolerance.Row, r.RingTolerance);
            r.Seed = f.Parameter(RopeParameters.BurrSeed.Row, r.Seed);
            ReadMaterialLaw(f, r);
            f.RejectUnknown();
        }

        /// <summary>The material law (issue 15): model, plastic law, energy absorber; with the plastic material the strains in order.</summary>
        static void ReadMaterialLaw(JsonFields f, RopeSpec r)
        {
            r.MaterialModel = f.Choice(RopeParameters.MaterialModel.Json, r.MaterialModel, "elastic", "elastic-plastic");
            r.YieldStrain = f.Parameter(RopeParameters.YieldStrain.Row, r.YieldStrain);
            r.HardeningModulus = f.Parameter(RopeParameters.HardeningModulus.Row, r.HardeningModulus);
            r.NeckingStrain = f.Parameter(RopeParameters.NeckingStrain.Row, r.NeckingStrain);
            r.UltimateStrain = f.Parameter(RopeParameters.UltimateStrain.Row, r.UltimateStrain);
            r.EnergyAbsorber = f.Parameter(RopeParameters.EnergyAbsorber.Row, r.EnergyAbsorber);
            r.AbsorberForce = f.Parameter(RopeParameters.AbsorberForce.Row, r.AbsorberForce);
            r.AbsorberDeployment = f.Parameter(RopeParameters.AbsorberDeployment.Row, r.AbsorberDeployment);
            if (!r.IsPlastic) return;
            if (!(r.YieldStrain < r.UltimateStrain))
                throw new ScenarioException(f.Child(RopeParameters.YieldStrain.Json),
                    $"must be below ultimateStrain ({JsonFields.Format(r.UltimateStrain)}): the rope yields before its break strain");
            if (!(r.NeckingStrain >= r.YieldStrain && r.NeckingStrain < r.UltimateStrain))
                throw new ScenarioException(f.Child(RopeParameters.NeckingStrain.Json),
                    $"must be in [yieldStrain, ultimateStrain) = [{JsonFields.Format(r.YieldStrain)}, {JsonFields.Format(r.UltimateStrain)})");
        }

        static void ReadDrag(JsonFields f, DragSpec d)
        {
            d.ViscousDrag = f.Parameter(RopeParameters.ViscousDrag.Row, d.ViscousDrag);
            d.DragCoefficient = f.Parameter(RopeParameters.DragCoefficient.Row, d.DragCoefficient);
            d.SkinFriction = f.Parameter(RopeParameters.SkinFriction.Row, d.SkinFriction);
            d.AirDensity = f.Parameter(RopeParameters.AirDensity.Row, d.AirDensity);
            d.Wind = f.Vector(RopeParameters.Wind.Json, d.Wind, RopeParameters.Wind.Max);
            f.RejectUnknown();
        }

        static AttachmentSpec ReadAttachment(JsonFields f, AttachmentSpec fallback)
        {
            if (f == null) return fallback;
            var a = new AttachmentSpec();
            string type = f.Choice("type", "fixed", "fixed", "keyframes", "body", "free");
            switch (type)
            {
                case "fixed":
                    a.Kind = AttachmentKind.Fixed;
                    a.Position = f.OptionalVector("position");
                    a.Compliance = f.Parameter(RopeParameters.AttachmentCompliance.Row, a.Compliance);
                    break;
                case "keyframes":
                    a.Kind = AttachmentKind.Keyframes;
                    a.Compliance = f.Parameter(RopeParameters.AttachmentCompliance.Row, a.Compliance);
                    var keys = f.Array("keys", MaxKeyframes);
                    if (keys.Count == 0) throw new ScenarioException(f.Child("keys"), "needs at least one keyframe");
                    for (int i = 0; i < keys.Count; i++)
                    {
                        var k = new JsonFields(keys[i], $"{f.Child("keys")}[{i}]");
                        var key = new Keyframe
                        {
                            Time = k.Number("time", double.NaN, 0, 1e5),
                            Position = k.Vector("position", new Float3(float.NaN, 0, 0)),
                        };
                        if (double.IsNaN(key.Time)) throw new ScenarioException(k.Child("time"), "required");
                        if (float.IsNaN(key.Position.X)) throw new ScenarioException(k.Child("position"), "required");
                        if (i > 0 && key.Time < a.Keys[i - 1].Time)
                            throw new ScenarioException(k.Child("time"), "keyframe times must not decrease");
                        k.RejectUnknown();
                        a.Keys.Add(key);
                    }
                    a.Position = a.Keys[0].Position;
                    break;
                case "body":
                    a.Kind = AttachmentKind.Body;
                    if (!f.Has("mass")) throw new ScenarioException(f.Child("mass"), "required for a body (kg)");
                    a.Mass = f.Number("mass", 0, 0, 1e7, minExclusive: true);
                    a.Position = f.OptionalVector("position");
                    a.Velocity = f.Vector("velocity", Float3.Zero, 1e4);
                    break;
                default:
                    a.Kind = AttachmentKind.Free;
                    a.Position = f.OptionalVector("position");
                    break;
            }
            f.RejectUnknown();
            return a;
        }

        /// <summary>Event type names in the JSON, in <see cref="EventKind"/> order.</summary>
        public static readonly string[] EventTypes = { "pin-target", "pin-velocity", "release-pin", "impulse", "damping", "cut" };

        static EventSpec ReadEvent(JsonFields f, Scenario s)
        {
            var e = new EventSpec();
            if (!f.Has("time")) throw new ScenarioException(f.Child("time"), "required (s, in [0, duration])");
            if (!f.Has("type")) throw new ScenarioException(f.Child("type"), "required: one of " + string.Join(", ", EventTypes));
            e.Time = f.Number("time", 0, double.NegativeInfinity, double.PositiveInfinity);
            if (e.Time < 0 || e.Time > s.Duration)
                throw new ScenarioException(f.Child("time"), $"{JsonFields.Format(e.Time)} s is outside the run [0, {JsonFields.Format(s.Duration)}] s");
            e.Type = f.Choice("type", "", EventTypes);
            e.Kind = (EventKind)System.Array.IndexOf(EventTypes, e.Type);
            switch (e.Kind)
            {
                case EventKind.PinTarget:
                case EventKind.PinVelocity:
                case EventKind.ReleasePin:
                {
                    if (!f.Has("end")) throw new ScenarioException(f.Child("end"), "required: \"start\" or \"end\"");
                    e.AtStart = f.Choice("end", "", "start", "end") == "start";
                    var held = e.AtStart ? s.Start : s.End;
                    if (held.Kind != AttachmentKind.Fixed && held.Kind != AttachmentKind.Keyframes)
                        throw new ScenarioException(f.Child("end"), $"the {(e.AtStart ? "start" : "end")} is not pinned (its type is not \"fixed\" or \"keyframes\")");
                    if (e.Kind == EventKind.PinTarget) e.Vector = Required(f, "position", 1e6);
                    if (e.Kind == EventKind.PinVelocity)
                    {
                        e.Vector = Required(f, "velocity", 1e4);
                        e.Until = f.Number("until", s.Duration, e.Time, s.Duration, minExclusive: true);
                    }
                    break;
                }
                case EventKind.Impulse:
                    e.Vector = Required(f, "impulse", 1e6);
                    e.At = f.Number("at", 1, 0, 1);
                    break;
                case EventKind.Damping:
                    if (!f.Has(RopeParameters.Damping.Json)) throw new ScenarioException(f.Child(RopeParameters.Damping.Json), "required (s)");
                    e.Value = f.Parameter(RopeParameters.Damping.Row, 0.0);
                    break;
                default:
                    if (!f.Has("at")) throw new ScenarioException(f.Child("at"), "required: where to cut, as a fraction of the rest length from the start (0…1)");
                    e.At = f.Number("at", 0.5, 0, 1);
                    break;
            }
            f.RejectUnknown();
            return e;
        }

        static Float3 Required(JsonFields f, string name, double limit)
        {
            if (!f.Has(name)) throw new ScenarioException(f.Child(name), "required");
            return f.Vector(name, Float3.Zero, limit);
        }

        static void ReadInitial(JsonFields f, InitialSpec spec)
        {
            string shape = f.Choice("shape", "straight", "straight", "slack", "catenary");
            spec.Shape = shape == "slack" ? InitialShape.Slack : shape == "catenary" ? InitialShape.Catenary : InitialShape.Straight;
            spec.Stretch = f.Number("stretch", 0, 0, 10);
            spec.FallHeight = f.OptionalNumber("fallHeight", 0, 1000, minExclusive: true);
            f.RejectUnknown();
        }

        static ColliderSpec ReadCollider(JsonFields f)
        {
            var c = new ColliderSpec();
            string type = f.Choice("type", "plane", "plane", "sphere", "capsule", "box");
            c.Friction = f.Parameter(RopeParameters.Friction.Row, c.Friction);
            switch (type)
            {
                case "plane":
                    c.Kind = ColliderKind.Plane;
                    c.Center = f.Vector("point", Float3.Zero);
                    c.Normal = f.Vector("normal", new Float3(0, 1, 0));
                    if (c.Normal.Length < 1e-6f) throw new ScenarioException(f.Child("normal"), "must not be zero");
                    c.Normal = c.Normal / c.Normal.Length;
                    break;
                case "sphere":
                    c.Kind = ColliderKind.Sphere;
                    c.Center = f.Vector("center", Float3.Zero);
                    c.Radius = f.Number("radius", c.Radius, 0, 1e4, minExclusive: true);
                    break;
                case "capsule":
                    c.Kind = ColliderKind.Capsule;
                    c.Center = f.Vector("a", new Float3(-0.5f, 0, 0));
                    c.PointB = f.Vector("b", new Float3(0.5f, 0, 0));
                    c.Radius = f.Number("radius", c.Radius, 0, 1e4, minExclusive: true);
                    break;
                default:
                    c.Kind = ColliderKind.Box;
                    c.Center = f.Vector("center", Float3.Zero);
                    c.HalfExtents = f.Vector("halfExtents", c.HalfExtents, 1e4);
                    if (c.HalfExtents.X <= 0 || c.HalfExtents.Y <= 0 || c.HalfExtents.Z <= 0)
                        throw new ScenarioException(f.Child("halfExtents"), "every half extent must be > 0 m");
                    c.EulerDegrees = f.Vector("rotation", Float3.Zero, 3600);
                    break;
            }
            f.RejectUnknown();
            return c;
        }

        static void ReadOutputs(JsonFields f, OutputSpec spec, double duration)
        {
            spec.SampleRate = f.Number("sampleRate", spec.SampleRate, 0, 100000);
            if (spec.SampleRate * duration > MaxRows)
                throw new ScenarioException(f.Child("sampleRate"), $"sampleRate × duration exceeds {MaxRows:G3} rows");
            spec.ProfileTimes = f.Numbers("profileTimes", MaxInstants, 0, duration);
            spec.GltfTimes = f.Numbers("gltfTimes", MaxInstants, 0, duration);
            f.RejectUnknown();
        }

        static void CrossCheck(Scenario s)
        {
            if (s.Initial.FallHeight.HasValue)
            {
                if (s.End.Kind != AttachmentKind.Body && s.End.Kind != AttachmentKind.Free)
                    throw new ScenarioException("$.initial.fallHeight", "needs a body or free end to raise");
                if (s.End.Position.HasValue)
                    throw new ScenarioException("$.initial.fallHeight", "cannot be combined with end.position (it places the end)");
                if (s.Start.Kind == AttachmentKind.Free || s.Start.Kind == AttachmentKind.Body)
                    throw new ScenarioException("$.initial.fallHeight", "needs a fixed or keyframed start");
                if (s.Initial.FallHeight.Value > 2 * s.Rope.RestLength)
                    throw new ScenarioException("$.initial.fallHeight",
                        $"at most 2 × rope.restLength ({JsonFields.Format(2 * s.Rope.RestLength)} m): the end is raised above the anchor by at most the rope length");
            }
            if (s.Initial.Shape == InitialShape.Catenary)
            {
                if (!s.Start.Position.HasValue || !s.End.Position.HasValue)
                    throw new ScenarioException("$.initial.shape", "catenary needs start.position and end.position");
                var chord = s.End.Position.Value - s.Start.Position.Value;
                if (chord.Length >= s.Rope.RestLength)
                    throw new ScenarioException("$.initial.shape", "catenary needs a span shorter than rope.restLength");
                var down = ScenarioGeometry.DownDirection(s.Gravity);
                if (Math.Abs(Float3.Dot(chord, down)) > 1e-4 * s.Rope.RestLength)
                    throw new ScenarioException("$.initial.shape", "catenary needs both ends at the same height");
            }
            if (s.Initial.Stretch > 0 && s.End.Position.HasValue)
                throw new ScenarioException("$.initial.stretch", "applies only when end.position is not given (the end is placed at L·(1 + stretch) below the start)");
        }
    }
}
