using NUnit.Framework;

namespace HookeRope.Tests.Components
{
    /// <summary>Edit mode, HookeRope assembly (in Unity and headless on the Unity stand-in): OnValidate's clamp names the value, its range and unit.</summary>
    [TestFixture]
    public sealed class RopeParameterLimitsTests
    {
        [Test]
        public void ClampMovesValueIntoRangeAndNamesIt()
        {
            float length = -3f;
            string message = RopeParameterLimits.Clamp(ref length, 0.01f, 1000f, 2f, "Rest length", "m");
            Assert.That(length, Is.EqualTo(0.01f));
            Assert.That(message, Does.Contain("Rest length").And.Contain("-3").And.Contain("[0.01, 1000] m"));
        }

        [Test]
        public void NaNBecomesTheFallback()
        {
            float radius = float.NaN;
            Assert.That(RopeParameterLimits.Clamp(ref radius, 1e-4f, 1f, 0.008f, "Radius", "m"), Is.Not.Null);
            Assert.That(radius, Is.EqualTo(0.008f));
        }

        [Test]
        public void ValueInRangeIsKeptSilently()
        {
            int substeps = 8;
            Assert.That(RopeParameterLimits.Clamp(ref substeps, 1, 1000, "Substeps"), Is.Null);
            Assert.That(substeps, Is.EqualTo(8));
        }
    }
}
