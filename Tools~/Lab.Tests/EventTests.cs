using System;
using System.IO;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Output;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Scenario format (issue 16 item 4): timed events, radius CSV, construction breaks, radius-model switches, bad input.</summary>
    [TestFixture]
    public sealed class EventTests : TempFolderTest
    {
        const double G = 9.81;

        static Scenario Parse(string json) => ScenarioParser.Parse(json);

        /// <summary>Centre of mass of the final particle positions (m), weighted by the particle masses.</summary>
        static double[] CentreOfMass(RunResult r)
        {
            var c = new double[3];
            double total = 0;
            int n = r.FinalPositions.Length / 3;
            for (int i = 0; i < n; i++)
            {
                double m = EventPlayer.ParticleMass(r.Scenario, i);
                total += m;
                for (int k = 0; k < 3; k++) c[k] += m * r.FinalPositions[3 * i + k];
            }
            for (int k = 0; k < 3; k++) c[k] /= total;
            return c;
        }

        static double TotalMass(Scenario s) => s.Rope.Mass + s.Start.LoadMass + s.End.LoadMass;

        [Test]
        public void ImpulseMovesTheCentreOfMassAtJOverM()
        {
            // A free 1 m rope with a 1 kg body, no gravity; 2 N·s sideways on the body at 0.5 s, 1 s to drift.
            const string json = @"{ ""gravity"": [0, 0, 0], ""duration"": 1.5, ""rope"": { ""restLength"": 1, ""segments"": 10, ""fracture"": false },
              ""start"": { ""type"": ""free"", ""position"": [0, 0, 0] }, ""end"": { ""type"": ""body"", ""mass"": 1, ""position"": [0, -1, 0] },
              ""events"": [ { ""time"": 0.5, ""type"": ""impulse"", ""impulse"": [0, 0, 2] } ] }";
            var s = Parse(json);
            var r = ScenarioRunner.Run(s);
            double expected = 2.0 / TotalMass(s) * 1.0;
            Assert.That(CentreOfMass(r)[2], Is.EqualTo(expected).Within(0.01 * expected));
            Assert.That(r.Events.Count, Is.EqualTo(1));
            Assert.That(r.Events[0].Time, Is.EqualTo(0.5).Within(1e-9));
        }

        [Test]
        public void PinVelocityMovesTheAnchorByVTimesTheInterval()
        {
            const string json = @"{ ""duration"": 1.5, ""rope"": { ""restLength"": 1, ""segments"": 10 }, ""end"": { ""type"": ""body"", ""mass"": 1 },
              ""events"": [ { ""time"": 0.5, ""type"": ""pin-velocity"", ""end"": ""start"", ""velocity"": [0.5, 0, 0], ""until"": 1.0 } ] }";
            var r = ScenarioRunner.Run(Parse(json));
            Assert.That(r.FinalPositions[0], Is.EqualTo(0.25).Within(1e-4), "x of the start: 0.5 m/s × 0.5 s");
            Assert.That(r.FinalPositions[1], Is.EqualTo(0).Within(1e-4));
        }

        [Test]
        public void PinTargetJumpsTheAnchor()
        {
            const string json = @"{ ""duration"": 1, ""rope"": { ""restLength"": 1, ""segments"": 10 }, ""end"": { ""type"": ""body"", ""mass"": 1 },
              ""events"": [ { ""time"": 0.5, ""type"": ""pin-target"", ""end"": ""start"", ""position"": [0, 0.3, 0] } ] }";
            var r = ScenarioRunner.Run(Parse(json));
            Assert.That(r.FinalPositions[1], Is.EqualTo(0.3).Within(1e-4));
        }

        [Test]
        public void ReleasedRopeFallsFreely()
        {
            const string hold = @"{ ""duration"": 1, ""rope"": { ""restLength"": 1, ""segments"": 10, ""fracture"": false }, ""end"": { ""type"": ""body"", ""mass"": 1 }, ""solver"": { ""damping"": 0.02 }";
            var held = ScenarioRunner.Run(Parse(hold + " }"));
            var released = ScenarioRunner.Run(Parse(hold + @", ""events"": [ { ""time"": 0.5, ""type"": ""release-pin"", ""end"": ""start"" } ] }"));
            double drop = CentreOfMass(held)[1] - CentreOfMass(released)[1];
            double expected = G * 0.5 * 0.5 / 2;   // 1.226 m in the last 0.5 s
            Assert.That(drop, Is.EqualTo(expected).Within(0.03 * expected));
        }

        [Test]
        public void DampingEventDampsTheOscillation()
        {
            var plain = BuiltInScenarios.Load("spring-oscillator");
            var damped = BuiltInScenarios.Load("spring-oscillator");
            damped.Events.Add(new EventSpec { Time = 0.2, Kind = EventKind.Damping, Value = 0.05 });
            double Spread(RunResult r)
            {
                var e = r.ElongationSeries;
                double min = double.MaxValue, max = double.MinValue;
                for (int i = e.Length * 2 / 3; i < e.Length; i++) { min = Math.Min(min, e[i]); max = Math.Max(max, e[i]); }
                return max - min;
            }
            double a = Spread(ScenarioRunner.Run(plain)), b = Spread(ScenarioRunner.Run(damped));
            Assert.That(b, Is.LessThan(0.2 * a), $"peak-to-peak elongation over the last third: {b} with β = 0.05 s against {a}");
        }

        [Test]
        public void CutIsReportedAsABreakAtItsTime()
        {
            const string json = @"{ ""duration"": 1, ""rope"": { ""restLength"": 1, ""segments"": 10 }, ""end"": { ""type"": ""body"", ""mass"": 1 },
              ""events"": [ { ""time"": 0.6, ""type"": ""cut"", ""at"": 0.55 } ] }";
            var r = ScenarioRunner.Run(Parse(json));
            Assert.That(r.BreakTime, Is.EqualTo(0.6).Within(1e-6));
            Assert.That(r.BrokenAtConstruction, Is.False);
            Assert.That(r.BreakTension, Is.EqualTo((1 + 0.45 * r.Scenario.Rope.Mass) * G).Within(0.1 * G), "the weight below the cut");
        }

        [Test]
        public void BreakWhileTheRopeIsBuiltIsReported()
        {
            const string json = @"{ ""name"": ""built-broken"", ""duration"": 0.2, ""rope"": { ""restLength"": 1, ""segments"": 10, ""breakStrain"": 0.5 },
              ""end"": { ""type"": ""body"", ""mass"": 1 }, ""initial"": { ""stretch"": 0.7 } }";
            var r = ScenarioRunner.Run(Parse(json));
            Assert.That(r.BrokenAtConstruction, Is.True);
            Assert.That(r.BreakTime, Is.EqualTo(0));
            string file = Path.Combine(dir, "s.json");
            File.WriteAllText(file, json);
            var o = new StringWriter();
            Assert.That(LabCli.Invoke(new[] { "run", file, "--out", dir }, LabConsole.Plain(o), o, o), Is.EqualTo(0));
            Assert.That(o.ToString(), Does.Contain("while the rope was built"));
            Assert.That(File.ReadAllText(Path.Combine(dir, "built-broken-summary.json")), Does.Contain("\"brokenDuringConstruction\": true"));
        }

        [Test]
        public void RadiusProfileCsvHasEveryInstantAtFullPrecision()
        {
            var o = new StringWriter();
            Assert.That(LabCli.Invoke(new[] { "run", "necking", "--out", dir }, LabConsole.Plain(o), o, o), Is.EqualTo(0), o.ToString());
            var lines = File.ReadAllLines(Path.Combine(dir, "necking-radius.csv"));
            Assert.That(lines[0], Is.EqualTo(CsvWriter.RadiusHeader));
            Assert.That(lines.Length, Is.EqualTo(1 + 5 * (21 * 8 + 1)), "3 requested instants and 2 key moments (neck onset, thinnest intact) × (8 points per segment + 1), 21 segments");
            Assert.That(System.Linq.Enumerable.Count(lines, l => l.Contains(",neck onset,")), Is.EqualTo(21 * 8 + 1));
            double thinnest = double.MaxValue;
            foreach (var line in lines)
            {
                if (line == lines[0]) continue;
                var f = line.Split(',');
                if (f[0] == "4") thinnest = Math.Min(thinnest, double.Parse(f[3], System.Globalization.CultureInfo.InvariantCulture));
            }
            Assert.That(thinnest, Is.LessThan(0.75 * 0.01), "the neck at 4 s is below r_min = 0.75 R");
            foreach (var line in File.ReadAllLines(Path.Combine(dir, "necking.csv")))
                foreach (var field in line.Split(',')) Assert.That(field, Is.Not.EqualTo("-0"));
        }

        [Test]
        public void NeckRadiusBreakCriterionCanBeTurnedOff()
        {
            string paper = BuiltInScenarios.Json("necking").Replace("\"neckMode\": \"zone\"", "\"neckMode\": \"paper\"")
                .Replace("\"fracture\": false", "\"fracture\": true, \"breakStrain\": 5");
            var on = ScenarioRunner.Run(Parse(paper));
            var off = ScenarioRunner.Run(Parse(paper.Replace("\"breakStrain\": 5", "\"breakStrain\": 5, \"breakRadiusFraction\": 0")));
            Assert.That(double.IsNaN(on.BreakTime), Is.False, "breaks by the neck radius (strain 0.9 < breakStrain 5)");
            Assert.That(double.IsNaN(off.BreakTime), Is.True, "breakRadiusFraction 0: only the strain criterion is left");
            Assert.That(SummaryView.MinRadius(off), Is.LessThan(0.25 * 0.01), "the neck deepened past 0.25 R without breaking");
        }

        [Test]
        public void EveryRadiusSwitchReachesTheRadiusModel()
        {
            var s = Parse(@"{ ""rope"": { ""poissonThinning"": false, ""poissonRatio"": 0.4, ""necking"": false, ""neckMode"": ""paper"", ""neckRadiusFraction"": 0.6,
              ""defectPosition"": 0.3, ""neckZoneDiameters"": 7, ""neckGrowthStrain"": 0.5, ""slackKeepsRestRadius"": false, ""fracture"": false,
              ""breakStrain"": 2, ""breakRadiusFraction"": 0 } }");
            var r = ScenarioRunner.RadiusSettings(s);
            Assert.That(r.PoissonThinning, Is.False);
            Assert.That(r.PoissonRatio, Is.EqualTo(0.4f));
            Assert.That(r.Necking, Is.False);
            Assert.That(r.NeckMode, Is.EqualTo(HookeRope.Radius.NeckMode.Paper));
            Assert.That(r.NeckRadiusFraction, Is.EqualTo(0.6f));
            Assert.That(r.DefectPosition, Is.EqualTo(0.3f));
            Assert.That(r.NeckZoneDiameters, Is.EqualTo(7f));
            Assert.That(r.NeckGrowthStrain, Is.EqualTo(0.5f));
            Assert.That(r.SlackKeepsRestRadius, Is.False);
            Assert.That(r.Fracture, Is.False);
            Assert.That(r.BreakStrain, Is.EqualTo(2f));
            Assert.That(r.BreakRadiusFraction, Is.EqualTo(0f));
        }

        [TestCase(@"{ ""events"": [ { ""time"": 7, ""type"": ""cut"", ""at"": 0.5 } ] }", "$.events[0].time", "outside the run [0, 5] s")]
        [TestCase(@"{ ""events"": [ { ""time"": -1, ""type"": ""cut"", ""at"": 0.5 } ] }", "$.events[0].time", "outside the run")]
        [TestCase(@"{ ""events"": [ { ""time"": 1, ""type"": ""cutt"", ""at"": 0.5 } ] }", "$.events[0].type", "did you mean \"cut\"")]
        [TestCase(@"{ ""events"": [ { ""time"": 1 } ] }", "$.events[0].type", "required")]
        [TestCase(@"{ ""events"": [ { ""time"": 1, ""type"": ""cut"" } ] }", "$.events[0].at", "required")]
        [TestCase(@"{ ""events"": [ { ""time"": 1, ""type"": ""impulse"" } ] }", "$.events[0].impulse", "required")]
        [TestCase(@"{ ""events"": [ { ""time"": 1, ""type"": ""release-pin"", ""end"": ""end"" } ] }", "$.events[0].end", "not pinned")]
        [TestCase(@"{ ""events"": [ { ""time"": 1, ""type"": ""pin-velocity"", ""end"": ""start"", ""velocity"": [1, 0, 0], ""until"": 0.5 } ] }", "$.events[0].until", "out of range")]
        [TestCase(@"{ ""events"": [ { ""time"": 1, ""type"": ""damping"", ""damping"": 0.1, ""extra"": 1 } ] }", "$.events[0].extra", "")]
        public void BadEventsNameTheField(string json, string path, string message)
        {
            var e = Assert.Throws<ScenarioException>(() => Parse(json));
            Assert.That(e.Path, Is.EqualTo(path));
            Assert.That(e.Message, Does.Contain(message));
            string file = Path.Combine(dir, "bad.json");
            File.WriteAllText(file, json);
            var o = new StringWriter();
            Assert.That(LabCli.Invoke(new[] { "run", file, "--out", dir }, LabConsole.Plain(o), o, o), Is.EqualTo(LabCli.InvalidInput));
            Assert.That(o.ToString(), Does.Contain(path));
        }
    }
}
