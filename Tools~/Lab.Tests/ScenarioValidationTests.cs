using HookeRope.Lab.Scenarios;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Every invalid scenario is rejected with a message that names the offending JSON path.</summary>
    [TestFixture]
    public sealed class ScenarioValidationTests
    {
        static ScenarioException Reject(string json) => Assert.Throws<ScenarioException>(() => ScenarioParser.Parse(json));

        /// <summary>Parsing <paramref name="json"/> fails at <paramref name="path"/>, with <paramref name="words"/> in the message when given.</summary>
        static void AssertRejectedAt(string json, string path, string words = null)
        {
            var e = Reject(json);
            Assert.That(e.Path, Is.EqualTo(path));
            if (words != null) Assert.That(e.Message, Does.Contain(words));
        }

        [TestCase("{\"rope\":{\"segmnts\":10}}", "$.rope.segmnts", "unknown field")]
        [TestCase("{\"colour\":1}", "$.colour", "unknown field")]
        [TestCase("{\"solver\":{\"method\":\"gauss-seidel\",\"extra\":true}}", "$.solver.extra", "unknown field")]
        [TestCase("{\"colliders\":[{\"type\":\"sphere\",\"centre\":[0,0,0]}]}", "$.colliders[0].centre", "unknown field")]
        [TestCase("{\"end\":{\"type\":\"keyframes\",\"keys\":[{\"time\":0,\"position\":[0,0,0],\"speed\":1}]}}", "$.end.keys[0].speed", "unknown field")]
        public void UnknownFieldsAreRejected(string json, string path, string words)
        {
            AssertRejectedAt(json, path, words);
        }

        [TestCase("{\"duration\":\"long\"}", "$.duration", "expected a number")]
        [TestCase("{\"rope\":{\"segments\":2.5}}", "$.rope.segments", "expected an integer")]
        [TestCase("{\"rope\":{\"segments\":\"20\"}}", "$.rope.segments", "expected an integer")]
        [TestCase("{\"rope\":[]}", "$.rope", "expected an object")]
        [TestCase("{\"gravity\":{\"y\":-9.81}}", "$.gravity", "expected [x, y, z]")]
        [TestCase("{\"gravity\":[0,\"down\",0]}", "$.gravity[1]", "expected a number")]
        [TestCase("{\"solver\":{\"method\":3}}", "$.solver.method", "expected a string")]
        [TestCase("{\"colliders\":{}}", "$.colliders", "expected an array")]
        [TestCase("{\"name\":true}", "$.name", "expected a string")]
        public void WrongTypesAreRejected(string json, string path, string words)
        {
            AssertRejectedAt(json, path, words);
        }

        [TestCase("{\"rope\":{\"segments\":0}}", "$.rope.segments")]
        [TestCase("{\"rope\":{\"segments\":10001}}", "$.rope.segments")]
        [TestCase("{\"rope\":{\"restLength\":-1}}", "$.rope.restLength")]
        [TestCase("{\"rope\":{\"radius\":0}}", "$.rope.radius")]
        [TestCase("{\"rope\":{\"poissonRatio\":0.7}}", "$.rope.poissonRatio")]
        [TestCase("{\"duration\":0}", "$.duration")]
        [TestCase("{\"hostStep\":0.5}", "$.hostStep")]
        [TestCase("{\"frameRate\":1}", "$.frameRate")]
        [TestCase("{\"solver\":{\"substeps\":0}}", "$.solver.substeps")]
        [TestCase("{\"solver\":{\"iterations\":5000}}", "$.solver.iterations")]
        [TestCase("{\"solver\":{\"damping\":-0.1}}", "$.solver.damping")]
        [TestCase("{\"solver\":{\"method\":\"jacobi\"}}", "$.solver.method")]
        [TestCase("{\"solver\":{\"integrator\":\"rk4\"}}", "$.solver.integrator")]
        [TestCase("{\"end\":{\"type\":\"body\",\"mass\":0}}", "$.end.mass")]
        [TestCase("{\"end\":{\"type\":\"body\"}}", "$.end.mass")]
        [TestCase("{\"colliders\":[{\"type\":\"sphere\",\"radius\":-2}]}", "$.colliders[0].radius")]
        [TestCase("{\"colliders\":[{\"type\":\"plane\",\"normal\":[0,0,0]}]}", "$.colliders[0].normal")]
        [TestCase("{\"outputs\":{\"profileTimes\":[1,99]}}", "$.outputs.profileTimes[1]")]
        [TestCase("{\"gravity\":[0,-1e9,0]}", "$.gravity[1]")]
        [TestCase("{\"end\":{\"type\":\"keyframes\",\"keys\":[{\"time\":1,\"position\":[0,0,0]},{\"time\":0.5,\"position\":[0,0,0]}]}}", "$.end.keys[1].time")]
        public void OutOfRangeValuesAreRejected(string json, string path)
        {
            AssertRejectedAt(json, path);
        }

        [Test]
        public void OversizedArraysAreRejected()
        {
            var colliders = new System.Text.StringBuilder("{\"colliders\":[");
            for (int i = 0; i <= ScenarioParser.MaxColliders; i++) colliders.Append(i == 0 ? "" : ",").Append("{\"type\":\"plane\"}");
            colliders.Append("]}");
            var e = Reject(colliders.ToString());
            Assert.That(e.Path, Is.EqualTo("$.colliders"));
            Assert.That(e.Message, Does.Contain("too many elements"));

            e = Reject("{\"gravity\":[0,-9.81,0,1]}");
            Assert.That(e.Path, Is.EqualTo("$.gravity"));
            Assert.That(e.Message, Does.Contain("exactly 3"));

            var times = new System.Text.StringBuilder("{\"outputs\":{\"gltfTimes\":[");
            for (int i = 0; i <= ScenarioParser.MaxInstants; i++) times.Append(i == 0 ? "0" : ",0");
            times.Append("]}}");
            e = Reject(times.ToString());
            Assert.That(e.Path, Is.EqualTo("$.outputs.gltfTimes"));
        }

        [TestCase("{\"rope\":{\"youngsModulus\":1e9,\"axialStiffness\":5000}}", "$.rope.axialStiffness")]
        [TestCase("{\"rope\":{\"linearDensity\":0.1,\"density\":1000}}", "$.rope.density")]
        [TestCase("{\"hostStep\":0.01,\"frameRate\":90}", "$.frameRate")]
        [TestCase("{\"end\":{\"type\":\"fixed\",\"position\":[0,-1,0]},\"initial\":{\"fallHeight\":1}}", "$.initial.fallHeight")]
        [TestCase("{\"rope\":{\"restLength\":1},\"end\":{\"type\":\"body\",\"mass\":1},\"initial\":{\"fallHeight\":3}}", "$.initial.fallHeight")]
        [TestCase("{\"rope\":{\"restLength\":1},\"end\":{\"type\":\"fixed\",\"position\":[2,0,0]},\"initial\":{\"shape\":\"catenary\"}}", "$.initial.shape")]
        [TestCase("{\"rope\":{\"segments\":1},\"rope \":{}}", "$.rope ")]
        [TestCase("{\"rope\":{},\"rope\":{}}", "$.rope")]
        public void ContradictionsAreRejected(string json, string path)
        {
            AssertRejectedAt(json, path);
        }

        [Test]
        public void MalformedJsonNamesTheLine()
        {
            var e = Reject("{\n  \"duration\": 1,\n  \"rope\": { \"segments\": 10, }\n}");
            Assert.That(e.Path, Is.EqualTo("$"));
            Assert.That(e.Message, Does.Contain("line 3"));
        }

        [Test]
        public void EmptyObjectGivesTheDocumentedDefaults()
        {
            var s = ScenarioParser.Parse("{}");
            Assert.That(s.Duration, Is.EqualTo(5.0));
            Assert.That(s.HostStep, Is.EqualTo(1.0 / 90).Within(1e-12));
            Assert.That(s.Solver.Method, Is.EqualTo(SolverMethod.ExactChain));
            Assert.That(s.Solver.Substeps, Is.EqualTo(RopeParameters.Substeps.Default));
            Assert.That(s.Solver.Iterations, Is.EqualTo(RopeParameters.Iterations.Default));
            Assert.That(s.Rope.Segments, Is.EqualTo(24));
            Assert.That(s.Rope.RestLength, Is.EqualTo(2.0));
            Assert.That(s.Gravity.Y, Is.EqualTo(-9.81f));
            Assert.That(s.Outputs.SampleRate, Is.EqualTo(200.0));
            double radius = RopeParameters.Radius.Default;
            Assert.That(s.Rope.ResolvedAxialStiffness, Is.EqualTo(1.5e8 * System.Math.PI * radius * radius).Within(1e-6));
        }

        [Test]
        public void FrameRateSetsTheHostStep()
        {
            Assert.That(ScenarioParser.Parse("{\"frameRate\":120}").HostStep, Is.EqualTo(1.0 / 120).Within(1e-15));
        }

        [Test]
        public void EveryBuiltInScenarioParses()
        {
            foreach (var name in BuiltInScenarios.Names)
            {
                var s = BuiltInScenarios.Load(name);
                Assert.That(s.Name, Is.EqualTo(name));
                Assert.That(s.Expect.Check, Is.Not.EqualTo("none"), name);
            }
        }

        [Test]
        public void UnknownScenarioNameListsTheBuiltIns()
        {
            var e = Assert.Throws<ScenarioException>(() => BuiltInScenarios.Resolve("no-such-scenario"));
            Assert.That(e.Message, Does.Contain("fall-arrest"));
        }
    }
}
