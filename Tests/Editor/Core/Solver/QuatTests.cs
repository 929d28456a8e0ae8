using System;
using HookeRope.Mathematics;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class QuatTests
    {
        [Test]
        public void RotationsMatchTheirAxisAndAngle()
        {
            Float3 v = Quat.FromAxisAngle(new Float3(0f, 0f, 1f), MathF.PI / 2f).Rotate(new Float3(1f, 0f, 0f));
            Assert.That(v.X, Is.EqualTo(0f).Within(1e-6f));
            Assert.That(v.Y, Is.EqualTo(1f).Within(1e-6f));
            Quat q = Quat.FromToRotation(new Float3(0f, 1f, 0f), new Float3(1f, 1f, 0f));
            Float3 w = q.Rotate(new Float3(0f, 2f, 0f));
            Assert.That(w.X, Is.EqualTo(MathF.Sqrt(2f)).Within(1e-5f));
            Assert.That(w.Y, Is.EqualTo(MathF.Sqrt(2f)).Within(1e-5f));
            Quat back = Quat.FromToRotation(new Float3(0f, 1f, 0f), new Float3(0f, -1f, 0f));
            Assert.That(back.Rotate(new Float3(0f, 1f, 0f)).Y, Is.EqualTo(-1f).Within(1e-5f));
            Quat both = Quat.FromAxisAngle(new Float3(0f, 1f, 0f), 0.4f) * Quat.FromAxisAngle(new Float3(0f, 1f, 0f), 0.6f);
            Float3 u = both.Rotate(new Float3(1f, 0f, 0f));
            Assert.That(u.X, Is.EqualTo(MathF.Cos(1f)).Within(1e-5f));
            Assert.That(u.Z, Is.EqualTo(-MathF.Sin(1f)).Within(1e-5f));
            Float3 r = q.Conjugate.Rotate(q.Rotate(new Float3(0.3f, -0.2f, 0.9f)));
            Assert.That(r.Z, Is.EqualTo(0.9f).Within(1e-5f));
            Assert.That(new Quat(0f, 0f, 0f, 0f).Normalized(), Is.EqualTo(Quat.Identity));
        }
    }
}
