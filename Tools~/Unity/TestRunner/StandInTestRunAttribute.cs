using System;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using NUnit.Framework.Internal;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: which of Unity's two test platforms a stand-in test assembly plays.</summary>
    internal enum StandInPlatform
    {
        /// <summary>Edit Mode: Application.isPlaying is false; scripts get no messages unless [ExecuteAlways].</summary>
        EditMode,

        /// <summary>Play Mode: Application.isPlaying is true; the player loop drives every script.</summary>
        PlayMode,
    }

    /// <summary>
    /// Not part of Unity: set on a stand-in test assembly, it plays Unity's Test Framework around every test. Before
    /// the run, a fresh scene in Edit or Play mode. Before each test, an empty console and no log expectations;
    /// after it, the test fails on an unexpected Error/Exception log or a missing expected one (LogAssert), and a
    /// frame left half-run by a [UnityTest] is finished. Objects a test leaves in the scene stay there, as in Unity.
    /// </summary>
    [AttributeUsage(AttributeTargets.Assembly)]
    internal sealed class StandInTestRunAttribute : Attribute, ITestAction
    {
        readonly StandInPlatform _platform;

        internal StandInTestRunAttribute(StandInPlatform platform) { _platform = platform; }

        public ActionTargets Targets => ActionTargets.Test | ActionTargets.Suite;

        public void BeforeTest(ITest test)
        {
            if (test.IsSuite)
            {
                if (test is TestAssembly)
                {
                    World.Reset();
                    World.IsPlaying = _platform == StandInPlatform.PlayMode;
                    RunEditorLoad();
                }
                return;
            }
            LogExpectations.Begin();
        }

        /// <summary>
        /// The editor's assembly load, when the run has the stand-in's UnityEditor beside it: its internal
        /// HookeRope.StandIn.EditorLoad.Run (the [InitializeOnLoad] static constructors, once per process). Found by
        /// name so that this assembly, which runtime test code also compiles against, does not reference UnityEditor.
        /// </summary>
        static void RunEditorLoad()
        {
            var load = Type.GetType("HookeRope.StandIn.EditorLoad, UnityEditor", throwOnError: false);
            load?.GetMethod("Run", System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Static)?.Invoke(null, null);
        }

        public void AfterTest(ITest test)
        {
            if (test.IsSuite) return;
            PlayerLoop.FinishFrame();
            string failure = LogExpectations.Failure();
            if (failure == null) return;
            var result = TestExecutionContext.CurrentContext.CurrentResult;
            if (result.ResultState.Status == TestStatus.Failed) return;
            result.SetResult(ResultState.Failure, failure);
        }
    }
}
