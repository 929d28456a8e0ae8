using HookeRope.Geometry;
using HookeRope.Mathematics;
using NUnit.Framework;

namespace HookeRope.Tests.Geometry
{
    /// <summary>The drawn ends land exactly on their attachments; the offsets fade linearly along a piece held at both ends and carry a piece held at one end whole.</summary>
    public sealed class EndAlignmentTests
    {
        static float[] Zeros(int n) => new float[n];

        [Test]
        public void PieceHeldAtBothEndsBlendsLinearly()
        {
            float[] x = Zeros(5), y = Zeros(5), z = Zeros(5);
            EndAlignment.Apply(x, y, z, new bool[4], true, new Float3(0.04f, 0f, 0f), true, new Float3(0f, -0.2f, 0f));
            Assert.That(x, Is.EqualTo(new[] { 0.04f, 0.03f, 0.02f, 0.01f, 0f }).Within(1e-7f));
            Assert.That(y, Is.EqualTo(new[] { 0f, -0.05f, -0.1f, -0.15f, -0.2f }).Within(1e-7f));
            Assert.That(z, Is.EqualTo(new float[5]));
        }

        [Test]
        public void BrokenRopeMovesEachPieceWithItsHolder()
        {
            float[] x = Zeros(6), y = Zeros(6), z = Zeros(6);
            var broken = new bool[5];
            broken[2] = true; // particles 0–2 hang from the start, 3–5 from the end
            EndAlignment.Apply(x, y, z, broken, true, new Float3(1f, 0f, 0f), true, new Float3(0f, 0f, 2f));
            Assert.That(x, Is.EqualTo(new[] { 1f, 1f, 1f, 0f, 0f, 0f }));
            Assert.That(z, Is.EqualTo(new[] { 0f, 0f, 0f, 2f, 2f, 2f }));
        }

        [Test]
        public void FreeEndGetsNoOffsetAndAPieceHeldAtOneEndMovesWhole()
        {
            float[] x = Zeros(4), y = Zeros(4), z = Zeros(4);
            EndAlignment.Apply(x, y, z, new bool[3], false, default, true, new Float3(0f, 0.5f, 0f));
            Assert.That(y, Is.EqualTo(new[] { 0.5f, 0.5f, 0.5f, 0.5f }));
        }
    }
}
