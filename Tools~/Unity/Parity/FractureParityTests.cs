using System;
using System.Collections.Generic;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Radius;
using HookeRope.Solver;
using HookeRope.Tests.Components;
using NUnit.Framework;
using UnityEngine;
using LabKeyframe = HookeRope.Lab.Scenarios.Keyframe;

namespace HookeRope.Tests.Parity
{
    /// <summary>
    /// One fracture path (issue 12): the same rope run through the lab's <see cref="ScenarioRunner"/> and through the
    /// <see cref="ElasticRope"/> component (on the Unity stand-in) breaks the same segment on the same host step with
    /// the same tension, and reports the same read-outs every step until 10 steps after the break.
    /// </summary>
    [TestFixture]
    public sealed class FractureParityTests
    {
        const int StepsAfterBreak = 10;
        const double Relative = 1e-6;

        /// <summary>What one side recorded: per host step the read-outs, and the break.</summary>
        sealed class Trace
        {
            public readonly List<double[]> Steps = new List<double[]>();
            public int BreakStep = -1;
            public int BreakSegment = -1;
            public double BreakTension = double.NaN;

            /// <summary>Records host step k's read-outs and the first break; true once the trace reaches 10 steps past the break.</summary>
            public bool Observe(int k, RopeReadouts readouts)
            {
                Steps.Add(Record(readouts));
                if (BreakStep < 0 && readouts.FirstBreak.HasValue)
                {
                    BreakStep = k;
                    BreakSegment = readouts.FirstBreak.Value.Segment;
                    BreakTension = readouts.FirstBreak.Value.Tension;
                }
                return BreakStep >= 0 && k >= BreakStep + StepsAfterBreak;
            }
        }

        static readonly string[] Quantities = { "top tension", "bottom tension", "peak tension", "elongation", "neck radius", "min radius", "residual" };

        static double[] Record(RopeReadouts r) => new double[]
        {
            r.TopTension, r.BottomTension, r.PeakTension, r.Elongation, r.NeckRadius, r.MinRadius, r.Residual,
        };

        /// <summary>The built-in fracture scenario: a cord pulled at 0.5 m/s until its defect (mid-rope) breaks at 50 % strain.</summary>
        static Scenario Fracture() => BuiltInScenarios.Resolve("fracture");

        /// <summary>The defect at 0.3 of the rope and gravity on: the defect breaks, not the most strained (top) segment.</summary>
        static Scenario DefectAtAThirdWithGravity()
        {
            var s = Fracture();
            s.Rope.DefectPosition = 0.3;
            s.Gravity = new Mathematics.Float3(0f, -9.81f, 0f);
            return s;
        }

        /// <summary>Necking on with breakRadiusFraction 0.5 (and a strain limit out of reach): the neck-radius rule breaks it.</summary>
        static Scenario NeckRadiusBreak()
        {
            var s = Fracture();
            s.Rope.Necking = true;
            s.Rope.NeckMode = "zone";
            s.Rope.NeckRadiusFraction = 0.75;
            s.Rope.BreakRadiusFraction = 0.5;
            s.Rope.BreakStrain = 5.0;
            s.End.Keys[1] = new LabKeyframe { Time = s.End.Keys[1].Time, Position = new Mathematics.Float3(3f, 0f, 0f) };
            return s;
        }

        static IEnumerable<TestCaseData> Cases()
        {
            yield return new TestCaseData((Func<Scenario>)Fracture, BreakReason.Strain).SetName("Parity fracture (built-in)");
            yield return new TestCaseData((Func<Scenario>)DefectAtAThirdWithGravity, BreakReason.Strain).SetName("Parity defect at 0.3 with gravity");
            yield return new TestCaseData((Func<Scenario>)NeckRadiusBreak, BreakReason.NeckRadius).SetName("Parity neck-radius break");
        }

        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        [TestCaseSource(nameof(Cases))]
        public void LabAndComponentBreakTheSameSegmentOnTheSameStep(Func<Scenario> make, BreakReason reason)
        {
            Scenario s = make();
            Trace lab = RunLab(s, out BreakReason labReason, out int defect);
            Trace component = RunComponent(s);

            Assert.That(lab.BreakStep, Is.GreaterThanOrEqualTo(0), "the lab run breaks");
            TestContext.WriteLine($"{s.Name}: lab broke segment {lab.BreakSegment} (defect {defect}, {labReason}) at step {lab.BreakStep} " +
                $"(t = {(lab.BreakStep + 1) * s.HostStep:F4} s) with {lab.BreakTension:F3} N; component: segment {component.BreakSegment} at step {component.BreakStep} with {component.BreakTension:F3} N");
            Assert.That(labReason, Is.EqualTo(reason));
            Assert.That(lab.BreakSegment, Is.EqualTo(defect), "the defect segment breaks");
            Assert.That(component.BreakSegment, Is.EqualTo(lab.BreakSegment), "same segment");
            Assert.That(component.BreakStep, Is.EqualTo(lab.BreakStep), "same host step");
            Assert.That(component.BreakTension, Is.EqualTo(lab.BreakTension).Within(Relative * Math.Abs(lab.BreakTension) + 1e-9), "same tension just before the break");
            Assert.That(component.Steps.Count, Is.EqualTo(lab.Steps.Count));
            for (int k = 0; k < lab.Steps.Count; k++)
                for (int q = 0; q < Quantities.Length; q++)
                {
                    double expected = lab.Steps[k][q], actual = component.Steps[k][q];
                    Assert.That(actual, Is.EqualTo(expected).Within(Relative * Math.Abs(expected) + 1e-12), $"{Quantities[q]} at step {k}");
                }
        }

        /// <summary>The lab's path: <see cref="ScenarioRunner.Build"/> and its step loop (keyframed pins moved to t = (k + 1)·Δt).</summary>
        static Trace RunLab(Scenario s, out BreakReason reason, out int defect)
        {
            var trace = new Trace();
            var setup = ScenarioRunner.Build(s);
            var readouts = setup.Simulation.Readouts;
            var model = setup.Simulation.RadiusModel;
            int d = defect = model.DefectSegment;
            var why = BreakReason.None;
            // which criterion fired, from the state the decision saw (the event is raised before anything moves)
            setup.Rope.Broken += e =>
            {
                double strain = setup.Rope.SegmentLengths[d] / setup.Rope.RestLengths[d] - 1.0;
                if (strain >= s.Rope.BreakStrain) why = BreakReason.Strain;
                else if (s.Rope.Necking && model.NeckRadius < s.Rope.BreakRadiusFraction * s.Rope.Radius) why = BreakReason.NeckRadius;
            };
            float dt = (float)s.HostStep;
            for (int k = 0; k < s.StepCount; k++)
            {
                double t = (k + 1) * s.HostStep;
                if (s.Start.Kind == AttachmentKind.Keyframes) setup.Rope.SetPinTarget(setup.StartPin, s.Start.PositionAt(t));
                if (s.End.Kind == AttachmentKind.Keyframes) setup.Rope.SetPinTarget(setup.EndPin, s.End.PositionAt(t));
                setup.Step(dt);
                if (trace.Observe(k, readouts)) break;
            }
            reason = why;
            return trace;
        }

        /// <summary>The component's path: an <see cref="ElasticRope"/> with the same values, its end Transform moved before each Simulate.</summary>
        Trace RunComponent(Scenario s)
        {
            var trace = new Trace();
            var r = s.Rope;
            Vector3 startPosition = ToVector3(s.Start.PositionAt(0)), endPosition = ToVector3(s.End.PositionAt(0));
            var start = _scene.Point("Start", startPosition);
            var end = _scene.Point("End", endPosition);
            var rope = _scene.Rope("Rope", startPosition);
            rope.CollisionMode = RopeCollisionMode.Off;
            rope.RestLength = (float)r.RestLength;
            rope.SegmentCount = r.Segments;
            rope.Radius = (float)r.Radius;
            rope.AxialStiffness = (float)r.AxialStiffness.Value;
            rope.Density = (float)r.Density.Value;
            rope.Damping = (float)s.Solver.Damping;
            rope.Gravity = ToVector3(s.Gravity);
            rope.Solver = s.Solver.Method == SolverMethod.GaussSeidel ? ConstraintSolverKind.GaussSeidel : ConstraintSolverKind.ExactChain;
            rope.Substeps = s.Solver.Substeps;
            rope.Iterations = s.Solver.Iterations;
            rope.TensionModel = s.Solver.TensionOnly ? TensionModel.TensionOnly : TensionModel.Bilateral;
            rope.AttachmentCompliance = (float)s.End.Compliance;
            rope.PoissonThinning = r.PoissonThinning;
            rope.PoissonRatio = (float)r.PoissonRatio;
            rope.NeckMode = r.NeckMode == "paper" ? NeckMode.Paper : NeckMode.Zone;
            rope.Necking = r.Necking;
            rope.NeckRadiusFraction = (float)r.NeckRadiusFraction;
            rope.DefectPosition = (float)r.DefectPosition;
            rope.Fracture = r.Fracture;
            rope.BreakStrain = (float)r.BreakStrain;
            rope.BreakRadiusFraction = (float)r.BreakRadiusFraction;
            rope.StartAttachment.Point = start;
            rope.EndAttachment.Point = end;
            rope.Rebuild();

            var readouts = rope.Simulation.Readouts;
            float dt = (float)s.HostStep;
            for (int k = 0; k < s.StepCount; k++)
            {
                double t = (k + 1) * s.HostStep;
                end.position = ToVector3(s.End.PositionAt(t));
                rope.Simulate(dt);
                if (trace.Observe(k, readouts)) break;
            }
            return trace;
        }

        static Vector3 ToVector3(Mathematics.Float3 v) => new Vector3(v.X, v.Y, v.Z);
    }
}
