using System;
using System.IO;
using HookeRope.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// Issue 18, "0 bytes per update": the ring budget's cap and the capacity it gives are stated in the manual with the
    /// numbers the code uses (Documentation~/radius-and-mesh.md, "Ring budget"), so a change of the cap cannot leave the
    /// page behind.
    /// </summary>
    [TestFixture]
    public sealed class RingBudgetDocumentationTests
    {
        static string Page() => File.ReadAllText(System.IO.Path.Combine(PackageRoot.Path, "Documentation~", "radius-and-mesh.md"));

        /// <summary>"8 755" as the manual writes numbers (thin groups of three separated by a space).</summary>
        static string Grouped(int value) => value.ToString("N0", System.Globalization.CultureInfo.InvariantCulture).Replace(",", " ");

        [Test]
        public void TheManualStatesTheCapAndTheCapacityOf64SegmentsWith16Sides()
        {
            string page = Page();
            Assert.That(page, Does.Contain("### Ring budget"));
            Assert.That(page, Does.Contain("MaxMeanRingsPerSegment = " + AdaptiveRings.MaxMeanRingsPerSegment));
            var builder = TubeMeshBuilder.Adaptive(new TubeMeshSettings { RadialSegments = 16 }, 64, 0.01f, null);
            Assert.That(page, Does.Contain(Grouped(builder.MostRings) + " rings"), "64 segments: rings at the cap");
            Assert.That(page, Does.Contain(Grouped(builder.GetVertexCapacity(ReadOnlySpan<bool>.Empty)) + " vertices"), "64 × 16: vertex capacity");
            Assert.That(page, Does.Contain(Grouped(builder.GetIndexCapacity(ReadOnlySpan<bool>.Empty)) + " indices"), "64 × 16: index capacity");
        }
    }
}
