using NUnit.Framework;
using NUnit.Framework.Interfaces;
using NUnit.Framework.Internal;
using NUnit.Framework.Internal.Builders;

namespace UnityEngine.TestTools
{
    /// <summary>
    /// Shim of UnityEngine.TestTools.UnityTestAttribute: an alternative to NUnit's Test attribute for tests that
    /// return IEnumerator and yield instructions (a coroutine in Play Mode, EditorApplication.update in Edit Mode).
    /// </summary>
    public class UnityTestAttribute : CombiningStrategyAttribute, ISimpleTestBuilder, IImplyFixture
    {
        /// <summary>Initializes and returns an instance of UnityTestAttribute.</summary>
        public UnityTestAttribute() : base(new CombinatorialStrategy(), new ParameterDataSourceProvider()) { }

        /// <summary>This method builds the TestMethod from the Test and the method info.</summary>
        TestMethod ISimpleTestBuilder.BuildFrom(IMethodInfo method, Test suite) => throw Shim.NotRun;
    }
}
