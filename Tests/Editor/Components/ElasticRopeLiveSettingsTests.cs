using System;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): parameter changes on a built rope apply at the next step without a new core rope;
    /// fields the core cannot change in place (segment count, attachments, collisions, friction, compliance) rebuild it
    /// at the next step, whether set from code or through the inspector (SerializedObject); bad values throw naming
    /// the parameter. The table below is the one in Documentation~/index.md, "Live edits".
    /// </summary>
    [TestFixture]
    public sealed class ElasticRopeLiveSettingsTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        ElasticRope HangingRope()
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var rope = _scene.Rope("Rope", anchor.position);
            rope.StartAttachment.Point = anchor;
            rope.SegmentCount = 12;
            rope.Rebuild();
            return rope;
        }

        [Test]
        public void MaterialChangeKeepsTheCoreRopeAndReachesItsSettings()
        {
            var rope = HangingRope();
            var core = rope.Simulation.Rope;
            rope.YoungsModulus = 2.5e8f;
            rope.Damping = 0.01f;
            rope.PoissonRatio = 0.45f;
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.SameAs(core));
            Assert.That(core.Settings.YoungsModulus, Is.EqualTo(2.5e8f).Within(1f));
            Assert.That(core.Settings.Damping, Is.EqualTo(0.01f).Within(1e-7f));
            Assert.That(rope.AxialStiffness, Is.EqualTo(2.5e8f * Mathf_Pi * rope.Radius * rope.Radius).Within(0.5f));
        }

        [Test]
        public void DragChangeKeepsTheCoreRopeAndReachesItsSettingsWithTheWindInWorldAxes()
        {
            var rope = HangingRope();
            rope.Simulate(0.02f);
            var core = rope.Simulation.Rope;
            Assert.That(core.Settings.HasDrag, Is.False, "drag is off by default");
            rope.ViscousDrag = 0.4f;
            rope.DragCoefficient = 1.1f;
            rope.SkinFriction = 0.01f;
            rope.AirDensity = 1.25f;
            rope.Wind = new Vector3(3f, 0f, -2f);
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.SameAs(core));
            Assert.That(core.Settings.ViscousDrag, Is.EqualTo(0.4f));
            Assert.That(core.Settings.DragCoefficient, Is.EqualTo(1.1f));
            Assert.That(core.Settings.SkinFriction, Is.EqualTo(0.01f));
            Assert.That(core.Settings.AirDensity, Is.EqualTo(1.25f));
            Assert.That(core.Settings.Wind, Is.EqualTo(new HookeRope.Mathematics.Float3(3f, 0f, -2f)), "the core frame is the world shifted, not turned");
            Assert.That(core.DragWork, Is.Not.EqualTo(0.0), "the air works on the rope");
        }

        [Test]
        public void NewSegmentCountRebuildsAtTheNextStep()
        {
            var rope = HangingRope();
            var core = rope.Simulation.Rope;
            rope.SegmentCount = 30;
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.Not.SameAs(core));
            Assert.That(rope.ParticleCount, Is.EqualTo(31));
        }

        [TestCase("RestLength")]
        [TestCase("Radius")]
        [TestCase("Density")]
        [TestCase("PoissonRatio")]
        [TestCase("Substeps")]
        [TestCase("ViscousDrag")]
        [TestCase("DragCoefficient")]
        [TestCase("AirDensity")]
        [TestCase("Wind")]
        public void OutOfRangeValueThrowsNamingTheParameter(string parameter)
        {
            var rope = HangingRope();
            TestDelegate set;
            switch (parameter)
            {
                case "RestLength": set = () => rope.RestLength = -1f; break;
                case "Radius": set = () => rope.Radius = 0f; break;
                case "Density": set = () => rope.Density = float.NaN; break;
                case "PoissonRatio": set = () => rope.PoissonRatio = 0.7f; break;
                case "ViscousDrag": set = () => rope.ViscousDrag = -0.5f; break;
                case "DragCoefficient": set = () => rope.DragCoefficient = -1f; break;
                case "AirDensity": set = () => rope.AirDensity = float.NaN; break;
                case "Wind": set = () => rope.Wind = new Vector3(0f, float.PositiveInfinity, 0f); break;
                default: set = () => rope.Substeps = 0; break;
            }
            var e = Assert.Throws<ArgumentOutOfRangeException>(set);
            Assert.That(e.ParamName, Is.EqualTo(parameter));
            Assert.That(e.Message, Does.Contain(parameter));
        }

        [Test]
        public void EndPointSetFromCodeTakesEffectAtTheNextStep()
        {
            var rope = HangingRope();
            UnityRopeScene.Run(rope, 5, 0.02f);
            var core = rope.Simulation.Rope;
            var hand = _scene.Point("Hand", new Vector3(1.5f, 4f, 0.5f));
            rope.EndAttachment.Point = hand;
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.Not.SameAs(core));
            int last = rope.ParticleCount - 1;
            Assert.That(Vector3.Distance(rope.GetParticlePosition(last), hand.position), Is.LessThan(1e-3f));
            hand.position = new Vector3(1.2f, 3.6f, 0.4f);
            var rebuilt = rope.Simulation.Rope;
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.SameAs(rebuilt), "moving the same point is a pose, not a topology change");
            Assert.That(Vector3.Distance(rope.GetParticlePosition(last), hand.position), Is.LessThan(1e-3f));
            Assert.That(rope.Simulation.Rope.PinCount, Is.EqualTo(2));
        }

        [Test]
        public void StartEditedThroughTheInspectorTakesEffectAtTheNextStep()
        {
            var rope = HangingRope();
            UnityRopeScene.Run(rope, 3, 0.02f);
            var core = rope.Simulation.Rope;
            var beam = _scene.Point("Beam", new Vector3(0.8f, 5.5f, -0.3f));
            var so = new SerializedObject(rope);
            so.FindProperty("m_Start.m_Point").objectReferenceValue = beam;
            so.ApplyModifiedProperties();
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.Not.SameAs(core));
            Assert.That(Vector3.Distance(rope.GetParticlePosition(0), beam.position), Is.LessThan(1e-3f));
        }

        [Test]
        public void FrictionEditedThroughTheInspectorRebuildsAtTheNextStep()
        {
            var rope = HangingRope();
            rope.Simulate(0.02f);
            var core = rope.Simulation.Rope;
            var so = new SerializedObject(rope);
            so.FindProperty("m_Friction").floatValue = 0.8f;
            so.ApplyModifiedProperties();
            Assert.That(rope.Friction, Is.EqualTo(0.8f));
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.Not.SameAs(core));
            var again = rope.Simulation.Rope;
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.SameAs(again), "no rebuild once the core matches the fields");
        }

        [Test]
        public void CollisionModeEditedThroughTheInspectorTakesEffectAtTheNextStep()
        {
            var rope = HangingRope();
            var ball = _scene.Track(new GameObject("Ball"));
            ball.transform.position = new Vector3(0.05f, 3f, 0f);
            var sphere = ball.AddComponent<SphereCollider>();
            rope.Colliders = new Collider[] { sphere };
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope.ColliderCount, Is.EqualTo(0), "mode Off registers nothing");
            var core = rope.Simulation.Rope;
            var so = new SerializedObject(rope);
            so.FindProperty("m_CollisionMode").intValue = (int)RopeCollisionMode.ListedColliders;
            so.ApplyModifiedProperties();
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.Not.SameAs(core));
            Assert.That(rope.Simulation.Rope.ColliderCount, Is.EqualTo(1));
        }

        // The documented table: each serialized field edited through the inspector during Play, and whether the
        // next step keeps the core rope (in place) or builds a new one (rebuild).
        [TestCase("m_StiffnessInput", 1, true)]
        [TestCase("m_YoungsModulus", 2e8f, true)]
        [TestCase("m_AxialStiffness", 5e4f, true)]
        [TestCase("m_Density", 900f, true)]
        [TestCase("m_PoissonRatio", 0.4f, true)]
        [TestCase("m_Damping", 0.02f, true)]
        [TestCase("m_RestLength", 3f, true)]
        [TestCase("m_Radius", 0.011f, true)]
        [TestCase("m_Solver", 0, true)]
        [TestCase("m_Substeps", 6, true)]
        [TestCase("m_Iterations", 3, true)]
        [TestCase("m_TensionModel", 1, true)]
        [TestCase("m_Integrator", 1 - (int)RopeParameters.Integrator.Default, true)]   // the other integrator
        [TestCase("m_GaussSeidelKernel", 1, true)]
        [TestCase("m_Gravity", -5f, true)]
        [TestCase("m_ViscousDrag", 0.3f, true)]
        [TestCase("m_DragCoefficient", 1.2f, true)]
        [TestCase("m_SkinFriction", 0.01f, true)]
        [TestCase("m_AirDensity", 1000f, true)]
        [TestCase("m_Wind", 4f, true)]
        [TestCase("m_NeckMode", 1, true)]
        [TestCase("m_NeckRadiusFraction", 0.6f, true)]
        [TestCase("m_DefectPosition", 0.3f, true)]
        [TestCase("m_BreakStrain", 0.5f, true)]
        [TestCase("m_BreakRadiusFraction", 0.2f, true)]
        [TestCase("m_MaterialModel", 1, true)]
        [TestCase("m_YieldStrain", 0.05f, true)]
        [TestCase("m_HardeningModulus", 0f, true)]
        [TestCase("m_NeckingStrain", 0.3f, true)]
        [TestCase("m_UltimateStrain", 0.8f, true)]
        [TestCase("m_EnergyAbsorber", 1, true)]
        [TestCase("m_AbsorberForce", 3000f, true)]
        [TestCase("m_AbsorberDeployment", 1f, true)]
        [TestCase("m_SegmentCount", 20, false)]
        [TestCase("m_RadiusModel", 1, false)]
        [TestCase("m_Necking", 1, false)]
        [TestCase("m_Fracture", 1, false)]
        [TestCase("m_End.m_Point", 0, false)]
        [TestCase("m_End.m_Body", 0, false)]
        [TestCase("m_AttachmentCompliance", 1e-4f, false)]
        [TestCase("m_CollisionMode", 2, false)]
        [TestCase("m_CollisionLayers", 4, false)]
        [TestCase("m_Colliders", 0, false)]
        [TestCase("m_Planes", 0, false)]
        [TestCase("m_Friction", 0.9f, false)]
        public void InspectorEditDuringPlayAppliesInPlaceOrRebuilds(string field, float value, bool inPlace)
        {
            var rope = HangingRope();
            rope.PoissonThinning = false;
            rope.Necking = false;
            rope.Fracture = false;
            rope.Rebuild();
            rope.Simulate(0.02f);
            var core = rope.Simulation.Rope;
            var so = new SerializedObject(rope);
            var property = so.FindProperty(field);
            Assert.That(property, Is.Not.Null, field);
            switch (field)
            {
                case "m_End.m_Point": property.objectReferenceValue = _scene.Point("Hand", new Vector3(0.5f, 3f, 0f)); break;
                case "m_End.m_Body": property.objectReferenceValue = _scene.Body("Load", new Vector3(0f, 2f, 0f), 80f); break;
                case "m_Gravity": property.vector3Value = new Vector3(0f, value, 0f); break;
                case "m_Wind": property.vector3Value = new Vector3(value, 0f, 0f); break;
                case "m_CollisionLayers": property.intValue = (int)value; break;
                case "m_Colliders":
                case "m_Planes":
                    property.arraySize = 1;
                    property.GetArrayElementAtIndex(0).objectReferenceValue = field == "m_Planes"
                        ? _scene.Point("Floor", Vector3.zero)
                        : (UnityEngine.Object)_scene.Track(new GameObject("Ball")).AddComponent<SphereCollider>();
                    break;
                default:
                    if (property.propertyType == SerializedPropertyType.Float) property.floatValue = value;
                    else if (property.propertyType == SerializedPropertyType.Boolean) property.boolValue = value != 0f;
                    else property.intValue = (int)value;
                    break;
            }
            Assert.That(so.ApplyModifiedProperties(), Is.True, field);
            rope.Simulate(0.02f);
            if (inPlace) Assert.That(rope.Simulation.Rope, Is.SameAs(core), field + " applies in place");
            else Assert.That(rope.Simulation.Rope, Is.Not.SameAs(core), field + " rebuilds");
        }

        [Test]
        public void RebuildButtonLogicBuildsANewCoreRopeNow()
        {
            var rope = HangingRope();
            rope.Simulate(0.02f);
            var core = rope.Simulation.Rope;
            rope.Rebuild();
            Assert.That(rope.Simulation.Rope, Is.Not.SameAs(core));
            Assert.That(rope.ParticleCount, Is.EqualTo(13));
        }

        const float Mathf_Pi = (float)Math.PI;
    }
}
