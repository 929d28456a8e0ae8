using System.Linq;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// The public surface of HookeRope.Core is a fixed list (issue 12): anything else is internal and reached by the
    /// package's own assemblies through InternalsVisibleTo. Adding a public type is a decision; make it here.
    /// </summary>
    [TestFixture]
    public sealed class PublicSurfaceTests
    {
        static readonly string[] s_Expected =
        {
            // Facade, read-outs, parameter table
            "HookeRope.RopeSimulation", "HookeRope.RopeReadouts",
            "HookeRope.RopeParameters", "HookeRope.ParameterInfo", "HookeRope.ParameterKind", "HookeRope.ParameterGroup",
            // Solver
            "HookeRope.Solver.Rope", "HookeRope.Solver.RopeSettings", "HookeRope.Solver.StepReport", "HookeRope.Solver.RopeBreakEvent",
            "HookeRope.Solver.ColliderShape", "HookeRope.Solver.ColliderKind", "HookeRope.Solver.ConstraintSolverKind", "HookeRope.Solver.TensionModel", "HookeRope.Solver.TimeIntegrator",
            // the opt-in fused single-precision Gauss–Seidel kernel (issue 18 item 1)
            "HookeRope.Solver.GaussSeidelKernel",
            // Material law (issue 15): the model, its quasi-static curve (inspector preview, lab plot), the fall-arrest limits the read-outs judge by
            "HookeRope.Solver.MaterialModel", "HookeRope.Solver.ForceElongationCurve", "HookeRope.FallArrestLimits",
            // Radius model (read-only queries) and its analytic formulas
            "HookeRope.Radius.RadiusSettings", "HookeRope.Radius.RadiusModel", "HookeRope.Radius.NeckMode", "HookeRope.Radius.BreakReason",
            "HookeRope.Radius.PoissonRadius", "HookeRope.Radius.NeckHyperbola",
            // Mesh data; the burr texture every renderer of the strands needs (the lab's figures, a glTF export, a non-Unity host)
            "HookeRope.Geometry.TubeMeshSettings", "HookeRope.Geometry.MeshFrame", "HookeRope.Fracture.BurrSettings", "HookeRope.Geometry.TubeVertex", "HookeRope.Geometry.LeanTubeVertex", "HookeRope.Geometry.TubeMeshUpdate",
            "HookeRope.Fracture.BurrTextureGenerator",
            // the ring tolerance by view distance (issue 18): the component's rule, for any host that draws many ropes
            "HookeRope.Geometry.ViewDetail",
            // Mathematics
            "HookeRope.Mathematics.Float3", "HookeRope.Mathematics.Quat",
            // Many ropes stepped on worker threads (issue 18 item 4) and the mesh buffers it fills
            "HookeRope.World.RopeWorld", "HookeRope.World.RopeMeshSlot",
        };

        [Test]
        public void CoreExportsExactlyTheAgreedTypes()
        {
            var exported = typeof(RopeSimulation).Assembly.GetExportedTypes()
                .Where(t => !t.IsNested).Select(t => t.FullName).OrderBy(n => n).ToList();
            var expected = s_Expected.OrderBy(n => n).ToList();
            Assert.That(exported, Is.EqualTo(expected), "exported: " + string.Join(", ", exported));
        }

        [Test]
        public void OnlyTheParameterTableNestsPublicTypes()
        {
            var nested = typeof(RopeSimulation).Assembly.GetExportedTypes()
                .Where(t => t.IsNested && t.DeclaringType != typeof(RopeParameters)).Select(t => t.FullName).ToList();
            Assert.That(nested, Is.Empty);
        }
    }
}
