using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// The Unity-dependent assemblies are compile-checked against our API shim (Tools~/Unity). These tests
    /// show that check has teeth: code calling a Unity member the shim lacks does not compile, and C# above 9
    /// (which Unity 2022.3 rejects) does not compile either.
    /// </summary>
    [TestFixture]
    public sealed class ShimCompileTests
    {
        static IEnumerable<Diagnostic> Compile(string source)
        {
            var references = ((string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES"))
                .Split(Path.PathSeparator)
                .Where(p => p.Length > 0)
                .Select(p => MetadataReference.CreateFromFile(p))
                .Append(MetadataReference.CreateFromFile(typeof(UnityEngine.MonoBehaviour).Assembly.Location));
            var tree = CSharpSyntaxTree.ParseText(source, new CSharpParseOptions(LanguageVersion.CSharp9));
            var compilation = CSharpCompilation.Create("ShimProbe", new[] { tree }, references,
                new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary));
            return compilation.GetDiagnostics().Where(d => d.Severity == DiagnosticSeverity.Error);
        }

        [Test]
        public void CodeUsingShimmedMembersCompiles()
        {
            const string source = "class Probe : UnityEngine.MonoBehaviour { void Move() { transform.position = new UnityEngine.Vector3(1, 2, 3); } }";
            Assert.That(Compile(source).Select(d => d.ToString()), Is.Empty);
        }

        [Test]
        public void CallToMemberTheShimLacksFails()
        {
            const string source = "class Probe : UnityEngine.MonoBehaviour { void Move() { transform.Teleport(1f); } }";
            var errors = Compile(source).ToList();
            Assert.That(errors.Select(d => d.Id), Has.Member("CS1061"));
            Assert.That(errors.Select(d => d.GetMessage()), Has.Some.Contains("Teleport"));
        }

        [Test]
        public void TypeTheShimLacksFails()
        {
            const string source = "class Probe { UnityEngine.Teleporter Gate; }";
            Assert.That(Compile(source).Select(d => d.Id), Has.Member("CS0234"));
        }

        [Test]
        public void CSharp10FeaturesFail()
        {
            const string source = "namespace Probe; class C { }";
            Assert.That(Compile(source).Select(d => d.Id), Has.Member("CS8773"));
        }
    }
}
