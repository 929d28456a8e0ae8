using System.Collections.Generic;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's Transform against documented Unity facts: world = parent · T · R · S (Transform.TransformPoint,
    /// localToWorldMatrix), Quaternion.Euler applies z, then x, then y (Quaternion.Euler page), rotations in a
    /// left-handed frame (rotating +X by 90° about +Y gives −Z), SetParent(parent, worldPositionStays).
    /// </summary>
    [TestFixture]
    public sealed class TransformFactsTests
    {
        [SetUp] public void SetUp() => World.Reset();
        [TearDown] public void TearDown() => World.Reset();

        static void AssertVector(Vector3 actual, Vector3 expected, float tolerance = 1e-5f)
        {
            Assert.That(actual.x, Is.EqualTo(expected.x).Within(tolerance), "x of " + actual);
            Assert.That(actual.y, Is.EqualTo(expected.y).Within(tolerance), "y of " + actual);
            Assert.That(actual.z, Is.EqualTo(expected.z).Within(tolerance), "z of " + actual);
        }

        [Test]
        public void IsChildOfIsTrueForTheTransformItselfAChildAndADeepChildOnly()
        {
            // Unity 2022.3 Transform.bindings.cs: IsChildOf is Internal_IsChildOrSameTransform, parent [NotNull]
            var root = new GameObject("Root").transform;
            var child = new GameObject("Child").transform;
            var deep = new GameObject("Deep").transform;
            var other = new GameObject("Other").transform;
            child.SetParent(root, false);
            deep.SetParent(child, false);
            Assert.That(root.IsChildOf(root), Is.True);
            Assert.That(child.IsChildOf(root), Is.True);
            Assert.That(deep.IsChildOf(root), Is.True);
            Assert.That(root.IsChildOf(child), Is.False);
            Assert.That(other.IsChildOf(root), Is.False);
            Assert.That(() => child.IsChildOf(null), Throws.TypeOf<System.ArgumentNullException>());
        }

        [Test]
        public void NonFinitePoseIsRefusedWithUnitysErrorAndTheOldValueKept()
        {
            var hand = new GameObject("Hand").transform;
            hand.position = new Vector3(1f, 2f, 3f);
            hand.rotation = Quaternion.Euler(0f, 90f, 0f);
            LogAssert.Expect(LogType.Error, new Regex(@"^transform\.position assign attempt for 'Hand' is not valid\. Input position is \{ NaN, 0\.000000, 0\.000000 \}\.$"));
            hand.position = new Vector3(float.NaN, 0f, 0f);
            LogAssert.Expect(LogType.Error, new Regex(@"^transform\.localPosition assign attempt for 'Hand' is not valid\. Input localPosition is"));
            hand.localPosition = new Vector3(0f, float.PositiveInfinity, 0f);
            LogAssert.Expect(LogType.Error, new Regex(@"^transform\.localRotation assign attempt for 'Hand' is not valid\. Input rotation is \{ NaN, 0\.000000, 0\.000000, 0\.000000 \}\.$"));
            hand.localRotation = new Quaternion(float.NaN, 0f, 0f, 0f);
            AssertVector(hand.position, new Vector3(1f, 2f, 3f));
            AssertVector(hand.rotation * Vector3.right, new Vector3(0f, 0f, -1f));
        }

        [Test]
        public void LogMessageReceivedSeesEveryConsoleEntryWithItsType()
        {
            var seen = new List<string>();
            Application.LogCallback collect = (condition, stackTrace, type) => seen.Add(type + ": " + condition);
            Application.logMessageReceived += collect;
            Debug.LogWarning("w");
            Debug.Log("l");
            Application.logMessageReceived -= collect;
            Debug.LogWarning("after");
            Assert.That(seen, Is.EqualTo(new[] { "Warning: w", "Log: l" }));
        }

        [Test]
        public void RotatingXBy90DegreesAboutYGivesMinusZ()
        {
            AssertVector(Quaternion.Euler(0f, 90f, 0f) * Vector3.right, new Vector3(0f, 0f, -1f));
            AssertVector(Quaternion.Euler(90f, 0f, 0f) * Vector3.up, new Vector3(0f, 0f, 1f));
        }

        [Test]
        public void EulerAppliesZThenXThenY()
        {
            var composed = Quaternion.Euler(0f, 30f, 0f) * Quaternion.Euler(20f, 0f, 0f) * Quaternion.Euler(0f, 0f, 10f);
            var v = new Vector3(0.3f, -1.2f, 2f);
            AssertVector(Quaternion.Euler(20f, 30f, 10f) * v, composed * v);
        }

        [Test]
        public void ChildWorldPositionComposesParentTranslationRotationScale()
        {
            var parent = new GameObject("Parent").transform;
            parent.position = new Vector3(1f, 2f, 3f);
            parent.rotation = Quaternion.Euler(0f, 90f, 0f);
            parent.localScale = new Vector3(2f, 2f, 2f);
            var child = new GameObject("Child").transform;
            child.SetParent(parent, false);
            child.localPosition = new Vector3(1f, 0f, 0f);

            AssertVector(child.position, new Vector3(1f, 2f, 1f));
            AssertVector(parent.TransformPoint(new Vector3(0f, 0.5f, 0f)), new Vector3(1f, 3f, 3f));
            AssertVector(parent.TransformDirection(Vector3.right), new Vector3(0f, 0f, -1f));
            AssertVector(parent.TransformVector(Vector3.right), new Vector3(0f, 0f, -2f));
            AssertVector(parent.InverseTransformPoint(child.position), child.localPosition);
            AssertVector(parent.InverseTransformVector(new Vector3(0f, 0f, -2f)), Vector3.right);
            AssertVector(parent.InverseTransformDirection(new Vector3(0f, 0f, -1f)), Vector3.right);
            AssertVector(child.lossyScale, new Vector3(2f, 2f, 2f));
        }

        [Test]
        public void SetParentKeepsTheWorldPoseOnlyWhenAsked()
        {
            var parent = new GameObject("Parent").transform;
            parent.position = new Vector3(0f, 5f, 0f);
            parent.localScale = new Vector3(1f, 4f, 1f);
            var kept = new GameObject("Kept").transform;
            kept.position = new Vector3(1f, 1f, 1f);
            kept.SetParent(parent, true);
            AssertVector(kept.position, new Vector3(1f, 1f, 1f));
            AssertVector(kept.localPosition, new Vector3(1f, -1f, 1f));
            AssertVector(kept.lossyScale, Vector3.one);

            var moved = new GameObject("Moved").transform;
            moved.position = new Vector3(1f, 1f, 1f);
            moved.SetParent(parent, false);
            AssertVector(moved.localPosition, new Vector3(1f, 1f, 1f));
            AssertVector(moved.position, new Vector3(1f, 9f, 1f));
            Assert.That(parent.childCount, Is.EqualTo(2));
            Assert.That(parent.GetChild(1), Is.SameAs(moved));
        }

        [Test]
        public void LossyScaleMultipliesAlongAlignedAxes()
        {
            var parent = new GameObject("Parent").transform;
            parent.localScale = new Vector3(2f, 3f, 4f);
            var child = new GameObject("Child").transform;
            child.SetParent(parent, false);
            child.localScale = new Vector3(0.5f, 2f, -1f);
            AssertVector(child.lossyScale, new Vector3(1f, 6f, -4f));
        }
    }
}
