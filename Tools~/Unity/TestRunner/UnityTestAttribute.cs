using System.Collections;
using System.Collections.Generic;
using HookeRope.StandIn;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using NUnit.Framework.Internal;
using NUnit.Framework.Internal.Builders;
using NUnit.Framework.Internal.Commands;

namespace UnityEngine.TestTools
{
    /// <summary>
    /// Stand-in of UnityEngine.TestTools.UnityTestAttribute: a test that returns IEnumerator and yields instructions.
    /// The stand-in drives it with its player loop: `yield return null` resumes after the next frame's Update (in
    /// Edit Mode, after the next editor update tick), `yield return new WaitForFixedUpdate()` after the next fixed
    /// step (Play Mode only), a nested IEnumerator runs to its end first. Any other instruction is unsupported.
    /// </summary>
    public class UnityTestAttribute : CombiningStrategyAttribute, ISimpleTestBuilder, IImplyFixture, ITestBuilder, IWrapTestMethod
    {
        readonly NUnitTestCaseBuilder _builder = new NUnitTestCaseBuilder();

        /// <summary>Initializes and returns an instance of UnityTestAttribute.</summary>
        public UnityTestAttribute() : base(new CombinatorialStrategy(), new ParameterDataSourceProvider()) { }

        /// <summary>This method builds the TestMethod from the Test and the method info.</summary>
        TestMethod ISimpleTestBuilder.BuildFrom(IMethodInfo method, Test suite)
        {
            // An IEnumerator return value is legal here: the result is the coroutine, not something to compare.
            var parameters = new TestCaseParameters { ExpectedResult = new object(), HasExpectedResult = true };
            return _builder.BuildTestMethod(method, suite, parameters);
        }

        /// <summary>Builds the test: one test for a parameterless method (the combining strategy would build none).</summary>
        IEnumerable<TestMethod> ITestBuilder.BuildFrom(IMethodInfo method, Test suite)
        {
            if (method.GetParameters().Length > 0) return BuildFrom(method, suite);
            return new[] { ((ISimpleTestBuilder)this).BuildFrom(method, suite) };
        }

        /// <summary>Not part of Unity's public surface: replaces the plain method call with the coroutine driver.</summary>
        TestCommand ICommandWrapper.Wrap(TestCommand command) => new CoroutineCommand((TestMethod)command.Test);

        sealed class CoroutineCommand : TestCommand
        {
            readonly TestMethod _method;

            internal CoroutineCommand(TestMethod method) : base(method) { _method = method; }

            public override TestResult Execute(TestExecutionContext context)
            {
                if (_method.Method.GetParameters().Length > 0) throw StandInError.Unsupported("[UnityTest] with parameters (" + _method.Name + ")");
                var routine = _method.Method.Invoke(context.TestObject, null) as IEnumerator;
                if (routine == null) throw StandInError.Unsupported("[UnityTest] " + _method.Name + " not returning IEnumerator");
                Drive(routine);
                context.CurrentResult.SetResult(ResultState.Success);
                return context.CurrentResult;
            }

            static void Drive(IEnumerator routine)
            {
                var stack = new Stack<IEnumerator>();
                stack.Push(routine);
                while (stack.Count > 0)
                {
                    var top = stack.Peek();
                    if (!top.MoveNext())
                    {
                        stack.Pop();
                        continue;
                    }
                    switch (top.Current)
                    {
                        case null:
                            PlayerLoop.RunUntil(LoopPoint.AfterUpdate);
                            break;
                        case WaitForFixedUpdate _ when World.IsPlaying:
                            PlayerLoop.RunUntil(LoopPoint.AfterFixedStep);
                            break;
                        case IEnumerator nested:
                            stack.Push(nested);
                            break;
                        default:
                            throw StandInError.Unsupported("yield return " + top.Current.GetType().Name + (World.IsPlaying ? "" : " in an Edit Mode test"));
                    }
                }
            }
        }
    }
}
