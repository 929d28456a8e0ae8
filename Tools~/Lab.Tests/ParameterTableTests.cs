using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using HookeRope.Lab.Scenarios;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// The lab's layer of the parameter table: every row with a JSON name is parsed with the row's range, the scenario
    /// specs default to the row's default, and lab.md documents the name. A row whose range, default or name the lab
    /// disagrees with fails here.
    /// </summary>
    [TestFixture]
    public sealed class ParameterTableTests
    {
        /// <summary>Where a row's JSON field lives and how to read its parsed value back (SI, as the row's unit).</summary>
        sealed class Field
        {
            public string Prefix;   // JSON text before the value
            public string Suffix;   // JSON text after the value
            public string Path;     // the JSON path of the field
            public Func<Scenario, double> Read;
        }

        static readonly Dictionary<string, Field> Numeric = new Dictionary<string, Field>
        {
            [RopeParameters.YoungsModulus.Name] = Rope(RopeParameters.YoungsModulus.Json, s => s.Rope.YoungsModulus ?? double.NaN),
            [RopeParameters.AxialStiffness.Name] = Rope(RopeParameters.AxialStiffness.Json, s => s.Rope.AxialStiffness ?? double.NaN),
            [RopeParameters.Density.Name] = Rope(RopeParameters.Density.Json, s => s.Rope.Density ?? double.NaN),
            [RopeParameters.LinearDensity.Name] = Rope(RopeParameters.LinearDensity.Json, s => s.Rope.LinearDensity ?? double.NaN),
            [RopeParameters.PoissonRatio.Name] = Rope(RopeParameters.PoissonRatio.Json, s => s.Rope.PoissonRatio),
            [RopeParameters.Damping.Name] = Solver(RopeParameters.Damping.Json, s => s.Solver.Damping),
            [RopeParameters.RestLength.Name] = Rope(RopeParameters.RestLength.Json, s => s.Rope.RestLength),
            [RopeParameters.Radius.Name] = Rope(RopeParameters.Radius.Json, s => s.Rope.Radius),
            [RopeParameters.SegmentCount.Name] = Rope(RopeParameters.SegmentCount.Json, s => s.Rope.Segments),
            [RopeParameters.Substeps.Name] = Solver(RopeParameters.Substeps.Json, s => s.Solver.Substeps),
            [RopeParameters.Iterations.Name] = Solver(RopeParameters.Iterations.Json, s => s.Solver.Iterations),
            [RopeParameters.AttachmentCompliance.Name] = new Field
            {
                Prefix = "{\"start\":{\"type\":\"fixed\",\"compliance\":", Suffix = "}}", Path = "$.start." + RopeParameters.AttachmentCompliance.Json,
                Read = s => s.Start.Compliance,
            },
            [RopeParameters.Friction.Name] = new Field
            {
                Prefix = "{\"colliders\":[{\"type\":\"sphere\",\"friction\":", Suffix = "}]}", Path = "$.colliders[0]." + RopeParameters.Friction.Json,
                Read = s => s.Colliders[0].Friction,
            },
            [RopeParameters.NeckRadiusFraction.Name] = Rope(RopeParameters.NeckRadiusFraction.Json, s => s.Rope.NeckRadiusFraction),
            [RopeParameters.DefectPosition.Name] = Rope(RopeParameters.DefectPosition.Json, s => s.Rope.DefectPosition),
            [RopeParameters.BreakStrain.Name] = Rope(RopeParameters.BreakStrain.Json, s => s.Rope.BreakStrain),
            [RopeParameters.NeckZoneDiameters.Name] = Rope(RopeParameters.NeckZoneDiameters.Json, s => s.Rope.NeckZoneDiameters),
            [RopeParameters.NeckGrowthStrain.Name] = Rope(RopeParameters.NeckGrowthStrain.Json, s => s.Rope.NeckGrowthStrain),
            [RopeParameters.BreakRadiusFraction.Name] = Rope(RopeParameters.BreakRadiusFraction.Json, s => s.Rope.BreakRadiusFraction),
            [RopeParameters.RadialSegments.Name] = Rope(RopeParameters.RadialSegments.Json, s => s.Rope.RadialSegments),
            [RopeParameters.RingTolerance.Name] = Rope(RopeParameters.RingTolerance.Json, s => s.Rope.RingTolerance),
            [RopeParameters.BurrSeed.Name] = Rope(RopeParameters.BurrSeed.Json, s => s.Rope.Seed),
            [RopeParameters.YieldStrain.Name] = Rope(RopeParameters.YieldStrain.Json, s => s.Rope.YieldStrain),
            [RopeParameters.HardeningModulus.Name] = Rope(RopeParameters.HardeningModulus.Json, s => s.Rope.HardeningModulus),
            [RopeParameters.NeckingStrain.Name] = Rope(RopeParameters.NeckingStrain.Json, s => s.Rope.NeckingStrain),
            [RopeParameters.UltimateStrain.Name] = Rope(RopeParameters.UltimateStrain.Json, s => s.Rope.UltimateStrain),
            [RopeParameters.AbsorberForce.Name] = Rope(RopeParameters.AbsorberForce.Json, s => s.Rope.AbsorberForce),
            [RopeParameters.AbsorberDeployment.Name] = Rope(RopeParameters.AbsorberDeployment.Json, s => s.Rope.AbsorberDeployment),
            [RopeParameters.ViscousDrag.Name] = Drag(RopeParameters.ViscousDrag.Json, s => s.Drag.ViscousDrag),
            [RopeParameters.DragCoefficient.Name] = Drag(RopeParameters.DragCoefficient.Json, s => s.Drag.DragCoefficient),
            [RopeParameters.SkinFriction.Name] = Drag(RopeParameters.SkinFriction.Json, s => s.Drag.SkinFriction),
            [RopeParameters.AirDensity.Name] = Drag(RopeParameters.AirDensity.Json, s => s.Drag.AirDensity),
        };

        /// <summary>Rows that are not a single number, with the default the spec reads as the row's number (enum value, bool 0/1).</summary>
        static readonly Dictionary<string, Func<Scenario, double>> Other = new Dictionary<string, Func<Scenario, double>>
        {
            [RopeParameters.Solver.Name] = s => (int)(s.Solver.Method == SolverMethod.GaussSeidel ? HookeRope.Solver.ConstraintSolverKind.GaussSeidel : HookeRope.Solver.ConstraintSolverKind.ExactChain),
            [RopeParameters.TensionModel.Name] = s => (int)(s.Solver.TensionOnly ? HookeRope.Solver.TensionModel.TensionOnly : HookeRope.Solver.TensionModel.Bilateral),
            [RopeParameters.Integrator.Name] = s => (int)s.Solver.Integrator,
            [RopeParameters.NeckMode.Name] = s => (int)(s.Rope.NeckMode == "paper" ? HookeRope.Radius.NeckMode.Paper : HookeRope.Radius.NeckMode.Zone),
            [RopeParameters.PoissonThinning.Name] = s => s.Rope.PoissonThinning ? 1 : 0,
            [RopeParameters.Necking.Name] = s => s.Rope.Necking ? 1 : 0,
            [RopeParameters.Fracture.Name] = s => s.Rope.Fracture ? 1 : 0,
            [RopeParameters.SlackKeepsRestRadius.Name] = s => s.Rope.SlackKeepsRestRadius ? 1 : 0,
            [RopeParameters.Gravity.Name] = s => double.NaN,
            [RopeParameters.MaterialModel.Name] = s => (int)(s.Rope.IsPlastic ? HookeRope.Solver.MaterialModel.ElasticPlastic : HookeRope.Solver.MaterialModel.Elastic),
            [RopeParameters.EnergyAbsorber.Name] = s => s.Rope.EnergyAbsorber ? 1 : 0,
            [RopeParameters.Wind.Name] = s => double.NaN,
        };

        static Field Rope(string json, Func<Scenario, double> read) =>
            new Field { Prefix = "{\"rope\":{\"" + json + "\":", Suffix = "}}", Path = "$.rope." + json, Read = read };

        static Field Drag(string json, Func<Scenario, double> read) =>
            new Field { Prefix = "{\"drag\":{\"" + json + "\":", Suffix = "}}", Path = "$.drag." + json, Read = read };

        static Field Solver(string json, Func<Scenario, double> read) =>
            new Field { Prefix = "{\"solver\":{\"" + json + "\":", Suffix = "}}", Path = "$.solver." + json, Read = read };

        static IEnumerable<ParameterInfo> JsonRows()
        {
            foreach (var row in RopeParameters.All)
                if (row.Json != null) yield return row;
        }

        static string Text(double value) => value.ToString("R", CultureInfo.InvariantCulture);

        [Test]
        public void EveryRowWithAJsonNameIsParsed()
        {
            var unmapped = new List<string>();
            foreach (var row in JsonRows())
                if (!Numeric.ContainsKey(row.Name) && !Other.ContainsKey(row.Name)) unmapped.Add(row.Name);
            Assert.That(unmapped, Is.Empty, "rows with a JSON name that this test (and so the parser) does not cover");
        }

        [Test]
        public void SpecDefaultsAreTheTableDefaults()
        {
            var fresh = new Scenario();
            foreach (var row in JsonRows())
            {
                if (row.Kind == ParameterKind.Vector) continue;
                double expected = row.Default;
                double actual;
                if (row.Name == RopeParameters.YoungsModulus.Name) actual = RopeSpec.DefaultYoungsModulus;
                else if (row.Name == RopeParameters.Density.Name) actual = RopeSpec.DefaultDensity;
                else if (row.Name == RopeParameters.AxialStiffness.Name || row.Name == RopeParameters.LinearDensity.Name) continue; // derived
                else if (row.Name == RopeParameters.Friction.Name) actual = new ColliderSpec().Friction;
                else if (Numeric.TryGetValue(row.Name, out var field)) actual = field.Read(fresh);
                else actual = Other[row.Name](fresh);
                Assert.That(actual, Is.EqualTo(expected), row.Name + " (" + row.Json + ")");
            }
            var g = RopeParameters.Gravity.Row.DefaultComponents;
            Assert.That(new[] { fresh.Gravity.X, fresh.Gravity.Y, fresh.Gravity.Z }, Is.EqualTo(new[] { g[0], g[1], g[2] }), "gravity");
        }

        [Test]
        public void TheParserAcceptsTheRangeAndRejectsJustOutsideIt()
        {
            foreach (var row in JsonRows())
            {
                if (!Numeric.TryGetValue(row.Name, out var field)) continue;
                bool integer = row.Kind == ParameterKind.Int;
                double low = row.MinExclusive ? (integer ? row.Min + 1 : NextUp(row.Min)) : row.Min;
                double high = row.MaxExclusive ? (integer ? row.Max - 1 : NextDown(row.Max)) : row.Max;
                foreach (double value in new[] { low, high })
                {
                    var s = ScenarioParser.Parse(field.Prefix + Text(value) + field.Suffix);
                    Assert.That(field.Read(s), Is.EqualTo(value), row.Name + " = " + Text(value));
                }
                double below = row.MinExclusive ? row.Min : integer ? row.Min - 1 : row.Min - Math.Max(Math.Abs(row.Min) * 1e-3, 1e-6);
                double above = row.MaxExclusive ? row.Max : integer ? row.Max + 1 : row.Max + Math.Max(Math.Abs(row.Max) * 1e-3, 1e-6);
                foreach (double value in new[] { below, above })
                {
                    var e = Assert.Throws<ScenarioException>(() => ScenarioParser.Parse(field.Prefix + Text(value) + field.Suffix), row.Name + " = " + Text(value));
                    Assert.That(e.Path, Is.EqualTo(field.Path), row.Name);
                }
            }
        }

        [Test]
        public void GravityComponentsFollowTheRow()
        {
            double max = RopeParameters.Gravity.Max;
            Assert.That(ScenarioParser.Parse("{\"gravity\":[0," + Text(max) + ",0]}").Gravity.Y, Is.EqualTo((float)max));
            var e = Assert.Throws<ScenarioException>(() => ScenarioParser.Parse("{\"gravity\":[0," + Text(max * 1.01) + ",0]}"));
            Assert.That(e.Path, Does.StartWith("$." + RopeParameters.Gravity.Json));
        }

        [Test]
        public void WindComponentsFollowTheRowAndDefaultToCalm()
        {
            double max = RopeParameters.Wind.Max;
            Assert.That(new Scenario().Drag.Wind, Is.EqualTo(HookeRope.Mathematics.Float3.Zero));
            Assert.That(ScenarioParser.Parse("{\"drag\":{\"wind\":[" + Text(max) + ",0,0]}}").Drag.Wind.X, Is.EqualTo((float)max));
            var e = Assert.Throws<ScenarioException>(() => ScenarioParser.Parse("{\"drag\":{\"wind\":[0,0," + Text(-max * 1.01) + "]}}"));
            Assert.That(e.Path, Does.StartWith("$.drag." + RopeParameters.Wind.Json));
        }

        [Test]
        public void EveryJsonNameIsInLabMd()
        {
            var dir = new DirectoryInfo(TestContext.CurrentContext.TestDirectory);
            while (dir != null && !File.Exists(Path.Combine(dir.FullName, "package.json"))) dir = dir.Parent;
            Assert.That(dir, Is.Not.Null, "package root");
            string doc = File.ReadAllText(Path.Combine(dir.FullName, "Documentation~", "lab.md"));
            foreach (var row in JsonRows()) Assert.That(doc, Does.Contain("`" + row.Json + "`"), row.Name);
        }

        static double NextUp(double value) => value == 0 ? 1e-9 : value + Math.Abs(value) * 1e-9;
        static double NextDown(double value) => value == 0 ? -1e-9 : value - Math.Abs(value) * 1e-9;
    }
}
