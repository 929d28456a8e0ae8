using NUnit.Framework;
using HookeRope.Editor;
using HookeRope.Solver;

namespace HookeRope.Tests.Components
{
    /// <summary>Edit mode, Editor assembly (in Unity and headless on the Unity stand-in): the inspector's stretch-error estimate behaves like the solvers' convergence.</summary>
    [TestFixture]
    public sealed class StretchErrorEstimateTests
    {
        const float Dt = 0.02f, Length = 2f, Stiffness = 30000f, Mu = 0.23f;

        [Test]
        public void ExactChainSolveHasNoPredictedError()
        {
            Assert.That(StretchErrorEstimate.Predict(24, Length, Stiffness, Mu, 100f, Dt, 1, 1, ConstraintSolverKind.ExactChain), Is.EqualTo(0.0));
        }

        [Test]
        public void GaussSeidelWithHeavyLoadAndFewSweepsIsWarned()
        {
            double error = StretchErrorEstimate.Predict(24, Length, Stiffness, Mu, 100f, Dt, 4, 2, ConstraintSolverKind.GaussSeidel);
            Assert.That(error, Is.GreaterThan(StretchErrorEstimate.WarningThreshold));
        }

        [Test]
        public void MoreSweepsAndLighterLoadsPredictLessError()
        {
            double few = StretchErrorEstimate.Predict(24, Length, Stiffness, Mu, 100f, Dt, 4, 2, ConstraintSolverKind.GaussSeidel);
            double many = StretchErrorEstimate.Predict(24, Length, Stiffness, Mu, 100f, Dt, 64, 8, ConstraintSolverKind.GaussSeidel);
            double light = StretchErrorEstimate.Predict(24, Length, Stiffness, Mu, 0f, Dt, 4, 2, ConstraintSolverKind.GaussSeidel);
            Assert.That(many, Is.LessThan(few));
            Assert.That(light, Is.LessThan(few));
            Assert.That(few, Is.InRange(0.0, 1.0));
        }
    }
}
