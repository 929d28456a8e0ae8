using HookeRope.Editor;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode, through the package prefab and Unity physics: the prefab dropped under a 100 kg worker Rigidbody
    /// with a "Harness D-Ring" child, 2 m above the floor, and wired by the inspector's fix (the self-wiring that
    /// Reset and a dropped prefab's Awake run) becomes an arresting lanyard: End pulls the worker at the D-ring,
    /// Start is a root-level anchor the rest length (2 m) above the D-ring. The worker, falling at
    /// v₀ = sqrt(2·g·h) as if after a free fall of h = 1 m, is arrested with the energy balance of a light linear
    /// lanyard F = M·g + sqrt((M·g)² + 2·M·g·k·h), k = E·A/L, undamped as in <see cref="WorkerFallArrestTests"/>: within
    /// −4 %/+2 % (measured −2.8 % at 50 Hz: the peak falls between steps, and the lanyard, at rest at build, is jerked
    /// into motion by the moving worker; the prefab's damping β = 2 ms lowers the peak by a further ≈ 2 %).
    /// And the fix decision: a rope whose End.Point is under a Rigidbody while End.Body is empty needs it. The anchor
    /// snaps to the underside of a beam 1.5 m above the D-ring (within the 2 m rest length), stays the rest length up
    /// when the beam is 2.1 m up, and skips the rig's, the rope's own and trigger colliders on the way.
    /// </summary>
    [TestFixture]
    public sealed class RopeAutoWiringTests
    {
        const string PrefabPath = "Packages/com.hookerope.elastic-rope/Runtime/Prefabs/ElasticRope.prefab";
        const float G = 9.81f, Mass = 100f, FreeFall = 1f;
        static readonly Vector3 DRingOffset = new Vector3(0f, 0.4f, 0.1f);
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        Rigidbody Worker(out Transform dRing) => _scene.Rig(new Vector3(0f, 2f, 0f), Mass, DRingOffset, out dRing);

        [Test]
        public void PrefabDroppedOnAWorkerRigIsWiredAndArrestsTheFall()
        {
            var worker = Worker(out var dRing);
            var prefab = AssetDatabase.LoadAssetAtPath<GameObject>(PrefabPath);
            Assert.That(prefab, Is.Not.Null, PrefabPath);
            var instance = (GameObject)PrefabUtility.InstantiatePrefab(prefab, worker.transform);
            var rope = instance.GetComponent<ElasticRope>();

            var fix = RopeAttachFix.For(rope);
            Assert.That(fix, Is.Not.Null, "the prefab's Start points at its own Anchor child, which now sits under the worker");
            fix.Apply();
            var anchor = rope.StartAttachment.Point;
            Assert.That(anchor, Is.Not.Null);
            _scene.Track(anchor.gameObject);

            Assert.That(rope.EndAttachment.Body, Is.SameAs(worker));
            Assert.That(rope.EndAttachment.Point, Is.SameAs(dRing));
            Assert.That(rope.StartAttachment.Body, Is.Null);
            Assert.That(anchor.parent, Is.Null, "the anchor is a root-level object, not carried by the rig");
            Assert.That(anchor.name, Is.EqualTo("Elastic Rope Anchor"));
            Assert.That((anchor.position - (dRing.position + new Vector3(0f, rope.RestLength, 0f))).magnitude, Is.LessThan(1e-5f));
            Assert.That(rope.RestLength, Is.EqualTo(2f));
            Assert.That(RopeAttachFix.For(rope), Is.Null, "a wired rope needs no fix");

            rope.Damping = 0f;
            rope.Rebuild();
            Assert.That(rope.GetParticlePosition(0).y - rope.GetParticlePosition(rope.ParticleCount - 1).y, Is.EqualTo(2f).Within(1e-4f),
                "at build the anchor is the rest length above the D-ring");

            const float dt = 0.02f;
            float weight = Mass * G, k = rope.AxialStiffness / rope.RestLength;
            float expected = weight + Sqrt(weight * weight + 2f * weight * k * FreeFall);
            worker.velocity = new Vector3(0f, -Sqrt(2f * G * FreeFall), 0f);
            float farthest = 0f;
            for (int i = 0; i < (int)(4f / dt); i++)
            {
                rope.Simulate(dt);
                Physics.Simulate(dt);
                farthest = System.Math.Max(farthest, (dRing.position - anchor.position).magnitude);
            }

            TestContext.WriteLine("peak " + rope.PeakArrestForce + " N, expected " + expected + " N (undamped), farthest " + farthest + " m");
            Assert.That(rope.PeakArrestForce, Is.GreaterThan(0f));
            Assert.That(rope.PeakArrestForce, Is.InRange(0.96f * expected, 1.02f * expected));
            Assert.That(rope.IsBroken, Is.False);
            Assert.That(farthest, Is.LessThan(rope.RestLength + 1.02f * expected / k), "the worker is held");
        }

        [Test]
        public void AnEndPointUnderARigidbodyWithoutBodyNeedsTheFix()
        {
            var worker = Worker(out var dRing);
            var beam = _scene.Point("Beam", new Vector3(0f, 6f, 0f));
            var rope = _scene.Rope("Lanyard", beam.position);
            rope.StartAttachment.Point = beam;
            rope.EndAttachment.Point = dRing;

            var fix = RopeAttachFix.For(rope);
            Assert.That(fix, Is.Not.Null);
            Assert.That(fix.Body, Is.SameAs(worker));
            Assert.That(fix.ButtonLabel, Is.EqualTo("Attach to Worker"));
            Assert.That(fix.EndPoint, Is.SameAs(dRing), "the End keeps the Point the user put on the body");
            Assert.That(fix.MovesStart, Is.False, "the Start already hangs from an anchor outside the rig");
            StringAssert.Contains("Worker", fix.Message);
            Assert.That(rope.EndAttachment.Body, Is.Null, "deciding changes nothing");

            fix.Apply();
            Assert.That(rope.EndAttachment.Body, Is.SameAs(worker));
            Assert.That(rope.EndAttachment.Point, Is.SameAs(dRing));
            Assert.That(rope.StartAttachment.Point, Is.SameAs(beam));
            Assert.That(RopeAttachFix.For(rope), Is.Null);
        }

        [Test]
        public void ARopeWithoutARigOrWithAPlainTransformEndNeedsNoFix()
        {
            var beam = _scene.Point("Beam", new Vector3(0f, 6f, 0f));
            var hand = _scene.Point("Hand", new Vector3(0f, 4f, 0f));
            var rope = _scene.Rope("Lanyard", beam.position);
            rope.StartAttachment.Point = beam;
            rope.EndAttachment.Point = hand;
            Assert.That(RopeAttachFix.For(rope), Is.Null);
        }

        // ---- the anchor snaps to the beam (the first collider above the D-ring within the rest length) --------------

        /// <summary>A rope under the worker whose End.Point is the D-ring while End.Body is empty: it needs the fix.</summary>
        ElasticRope RopeOnWorker(Rigidbody worker, Transform dRing)
        {
            var rope = _scene.Rope("Lanyard", worker.position);
            rope.transform.SetParent(worker.transform, true);
            rope.RestLength = 2f;
            rope.EndAttachment.Point = dRing;
            return rope;
        }

        /// <summary>A 4 m × 0.2 m × 0.4 m box beam along x centred at height <paramref name="centreY"/> (m): underside at centreY − 0.1.</summary>
        BoxCollider Beam(float centreY)
        {
            var beam = _scene.Point("Beam", new Vector3(0f, centreY, 0f)).gameObject.AddComponent<BoxCollider>();
            beam.size = new Vector3(4f, 0.2f, 0.4f);
            return beam;
        }

        [Test]
        public void TheAnchorSnapsToTheUndersideOfABeamWithinReach()
        {
            var worker = Worker(out var dRing); // D-ring at (0, 2.4, 0.1)
            var beam = Beam(4f);                // underside y = 3.9: 1.5 m above the D-ring, within the 2 m rest length
            var rope = RopeOnWorker(worker, dRing);

            var fix = RopeAttachFix.For(rope);
            Assert.That(fix, Is.Not.Null);
            Assert.That(fix.MovesStart, Is.True);
            Assert.That(fix.Beam, Is.SameAs(beam));
            Assert.That((fix.AnchorPosition - new Vector3(0f, 3.9f, 0.1f)).magnitude, Is.LessThan(1e-5f));
            StringAssert.Contains("snapped to 'Beam', 1.5 m above it", fix.Message);

            fix.Apply();
            var anchor = rope.StartAttachment.Point;
            _scene.Track(anchor.gameObject);
            Assert.That(anchor.parent, Is.Null);
            Assert.That((anchor.position - new Vector3(0f, 3.9f, 0.1f)).magnitude, Is.LessThan(1e-5f), "on the beam's underside");
            Assert.That(rope.EndAttachment.Body, Is.SameAs(worker));

            rope.Rebuild();
            Assert.That((rope.GetParticlePosition(0) - anchor.position).magnitude, Is.LessThan(1e-5f));
            Assert.That((rope.GetParticlePosition(rope.ParticleCount - 1) - dRing.position).magnitude, Is.LessThan(1e-5f));
        }

        [Test]
        public void ABeamBeyondReachLeavesTheAnchorTheRestLengthAbove()
        {
            var worker = Worker(out var dRing);
            Beam(4.6f); // underside y = 4.5: 2.1 m above the D-ring, beyond the 2 m rest length
            var rope = RopeOnWorker(worker, dRing);

            var fix = RopeAttachFix.For(rope);
            Assert.That(fix.Beam, Is.Null);
            Assert.That((fix.AnchorPosition - new Vector3(0f, 4.4f, 0.1f)).magnitude, Is.LessThan(1e-5f));
            StringAssert.DoesNotContain("snapped", fix.Message);
            StringAssert.Contains("'Lanyard Anchor' 2 m above it", fix.Message);
        }

        [Test]
        public void AnExistingRootAnchorIsReusedWhereItStandsAndTheMessageSaysSo()
        {
            var worker = Worker(out var dRing);
            Beam(4f); // within reach, but the user's own anchor wins
            var existing = _scene.Point("Lanyard Anchor", new Vector3(1f, 5f, 0f));
            var rope = RopeOnWorker(worker, dRing);

            var fix = RopeAttachFix.For(rope);
            StringAssert.Contains("the existing 'Lanyard Anchor', kept where it is", fix.Message);
            StringAssert.DoesNotContain("snapped", fix.Message);
            fix.Apply();
            Assert.That(rope.StartAttachment.Point, Is.SameAs(existing));
            Assert.That((existing.position - new Vector3(1f, 5f, 0f)).magnitude, Is.EqualTo(0f), "not moved");
        }

        [Test]
        public void TheRigsTheRopesAndTriggerCollidersAboveTheDRingAreIgnored()
        {
            var worker = Worker(out var dRing);
            var helmet = new GameObject("Helmet").AddComponent<SphereCollider>();   // the rig's own, 0.45 m above the D-ring
            helmet.transform.SetParent(worker.transform, false);
            helmet.transform.localPosition = DRingOffset + new Vector3(0f, 0.6f, 0f);
            helmet.radius = 0.15f;
            var beam = Beam(4f);
            var rope = _scene.Rope("Lanyard", worker.position); // at the root: the rig is found through End.Point
            rope.RestLength = 2f;
            rope.EndAttachment.Point = dRing;
            var ropeOwn = new GameObject("Rope Clip").AddComponent<BoxCollider>();   // the rope's own, 0.7 m above
            ropeOwn.transform.SetParent(rope.transform, false);
            ropeOwn.transform.position = dRing.position + new Vector3(0f, 0.8f, 0f);
            ropeOwn.size = new Vector3(0.2f, 0.2f, 0.2f);
            var zone = _scene.Point("Safety Zone", dRing.position + new Vector3(0f, 1f, 0f)).gameObject.AddComponent<BoxCollider>();
            zone.isTrigger = true;                                                     // a trigger, entered 0.5 m above

            Physics.SyncTransforms(); // colliders moved after they were added reach the queries at a sync
            Assert.That(Physics.RaycastAll(dRing.position, Vector3.up, 2f, Physics.DefaultRaycastLayers, QueryTriggerInteraction.Collide).Length,
                Is.EqualTo(4), "all four are on the ray within reach");
            var fix = RopeAttachFix.For(rope);
            Assert.That(fix.Beam, Is.SameAs(beam));
            Assert.That((fix.AnchorPosition - new Vector3(0f, 3.9f, 0.1f)).magnitude, Is.LessThan(1e-5f));
        }

        static float Sqrt(float x) => (float)System.Math.Sqrt(x);
    }
}
