using System.IO;
using HookeRope.Lab.Commands;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>The command line end to end: files written, summary printed, errors without stack traces.</summary>
    [TestFixture]
    public sealed class CliTests : TempFolderTest
    {
        static int Invoke(out string output, out string error, params string[] args) => InvokeLab(out output, out error, args);

        [Test]
        public void DefaultRunWritesCsvPlotAndSummary()
        {
            int code = Invoke(out string output, out string error, "run", "--out", dir);
            Assert.That(code, Is.EqualTo(0), error);
            string csv = Path.Combine(dir, "fall-arrest.csv");
            Assert.That(File.Exists(csv), Is.True);
            var lines = File.ReadAllLines(csv);
            Assert.That(lines[0], Does.StartWith("time_s,load_x_m"));
            Assert.That(lines.Length, Is.EqualTo(1 + 1 + 270), "header, t = 0 and one row per host step (sampleRate 0) over 3 s at 90 Hz");
            var png = File.ReadAllBytes(Path.Combine(dir, "fall-arrest-force.png"));
            Assert.That(png.Length, Is.GreaterThan(1000));
            Assert.That(png[1], Is.EqualTo((byte)'P'));
            Assert.That(output, Does.Contain("peak anchor force"));
            Assert.That(output, Does.Contain("EN 355"));
            Assert.That(output, Does.Contain("arrest distance"));
        }

        [Test]
        public void GltfExportWritesABinaryGltfWithBrokenEnds()
        {
            int code = Invoke(out _, out string error, "run", "fracture", "--gltf", "--out", dir);
            Assert.That(code, Is.EqualTo(0), error);
            var glb = File.ReadAllBytes(Path.Combine(dir, "fracture-t1.500.glb"));
            Assert.That(System.Text.Encoding.ASCII.GetString(glb, 0, 4), Is.EqualTo("glTF"));
            var model = SharpGLTF.Schema2.ModelRoot.Load(Path.Combine(dir, "fracture-t1.500.glb"));
            var positions = model.LogicalMeshes[0].Primitives[0].GetVertexAccessor("POSITION").AsVector3Array();
            Assert.That(positions.Count, Is.GreaterThan(100));
            foreach (var p in positions) Assert.That(float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z), Is.True);
            // Issue 17: the burr fibres are a second primitive with their own material.
            var primitives = model.LogicalMeshes[0].Primitives;
            Assert.That(primitives.Count, Is.EqualTo(2));
            Assert.That(primitives[0].Material.Name, Is.EqualTo("rope"));
            Assert.That(primitives[1].Material.Name, Is.EqualTo("burr fibres"));
            Assert.That(primitives[1].IndexAccessor.Count, Is.EqualTo(2 * 126 * 9), "two broken ends of 126 fibres (R = 10 mm), three triangles each");
        }

        [Test]
        public void InvalidScenarioFileNamesTheFieldWithoutAStackTrace()
        {
            string file = Path.Combine(dir, "bad.json");
            File.WriteAllText(file, "{ \"rope\": { \"segments\": 20, \"youngsModulus\": \"stiff\" } }");
            int code = Invoke(out _, out string error, "run", file, "--out", dir);
            Assert.That(code, Is.EqualTo(LabCli.InvalidInput));
            Assert.That(error, Does.Contain("$.rope.youngsModulus"));
            Assert.That(error, Does.Not.Contain("   at "));
        }

        [Test]
        public void UnknownOptionIsAParseError()
        {
            int code = Invoke(out _, out string error, "run", "--frobnicate", "--out", dir);
            Assert.That(code, Is.EqualTo(LabCli.InvalidInput));
            Assert.That(error, Does.Not.Contain("   at "));
        }

        [Test]
        public void CheckFlagPassesOnACorrectScenario()
        {
            Assert.That(Invoke(out _, out string error, "run", "catenary", "--check", "--out", dir), Is.EqualTo(0), error);
        }
    }
}
