using NUnit.Framework;
using HookeRope.Solver;
using UnityEditor;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): the package's prefab, loaded as an asset and instantiated as the Editor does, carries the
    /// settings written in its YAML (so a renamed serialized field shows up here), references its own Anchor child,
    /// and the rope it builds hangs with the textbook top tension μ·L·g (less the pinned particle's half segment).
    /// </summary>
    [TestFixture]
    public sealed class ElasticRopePrefabTests
    {
        const string PrefabPath = "Packages/com.hookerope.elastic-rope/Runtime/Prefabs/ElasticRope.prefab";
        const float G = 9.81f;
        GameObject _instance;

        [TearDown]
        public void TearDown()
        {
            if (_instance != null) Object.DestroyImmediate(_instance);
        }

        ElasticRope Instantiate()
        {
            var prefab = AssetDatabase.LoadAssetAtPath<GameObject>(PrefabPath);
            Assert.That(prefab, Is.Not.Null, PrefabPath);
            _instance = (GameObject)PrefabUtility.InstantiatePrefab(prefab);
            return _instance.GetComponent<ElasticRope>();
        }

        [Test]
        public void InstanceCarriesTheSerializedSettings()
        {
            var rope = Instantiate();
            Assert.That(_instance.name, Is.EqualTo("Elastic Rope"));
            Assert.That(rope, Is.Not.Null);
            Assert.That(rope.YoungsModulus, Is.EqualTo(1.5e8f).Within(1f));
            Assert.That(rope.AxialStiffness, Is.EqualTo(1.5e8f * Mathf_Pi * 0.008f * 0.008f).Within(0.5f), "E·A follows E and R");
            Assert.That(rope.Density, Is.EqualTo(1140f));
            Assert.That(rope.PoissonRatio, Is.EqualTo(0.3f).Within(1e-7f));
            Assert.That(rope.Damping, Is.EqualTo(0.002f).Within(1e-9f));
            Assert.That(rope.RestLength, Is.EqualTo(2f));
            Assert.That(rope.Radius, Is.EqualTo(0.008f).Within(1e-9f));
            Assert.That(rope.SegmentCount, Is.EqualTo(24));
            Assert.That(rope.Solver, Is.EqualTo(ConstraintSolverKind.ExactChain));
            Assert.That(rope.Substeps, Is.EqualTo(8));
            Assert.That(rope.Iterations, Is.EqualTo(1));
            Assert.That(rope.Integrator, Is.EqualTo(RopeParameters.Integrator.Default), "the prefab's m_Integrator is the table's default (change both together)");
            Assert.That(rope.Gravity.y, Is.EqualTo(-9.81f).Within(1e-6f));
            Assert.That(rope.AttachmentCompliance, Is.EqualTo(0f));
            Assert.That(rope.CollisionMode, Is.EqualTo(RopeCollisionMode.Off));
            Assert.That(rope.Colliders.Length, Is.EqualTo(0));
            Assert.That(rope.Planes.Length, Is.EqualTo(0));
            Assert.That(rope.Friction, Is.EqualTo(0.3f).Within(1e-7f));
            Assert.That(rope.PoissonThinning, Is.True);
            Assert.That(rope.Necking, Is.True);
            Assert.That(rope.NeckRadiusFraction, Is.EqualTo(0.75f));
            Assert.That(rope.DefectPosition, Is.EqualTo(0.5f));
            Assert.That(rope.Fracture, Is.True);
            Assert.That(rope.BreakStrain, Is.EqualTo(0.6f).Within(1e-7f));
            Assert.That(rope.BreakRadiusFraction, Is.EqualTo(0.25f));
            Assert.That(rope.OnBreak.GetPersistentEventCount(), Is.EqualTo(0));

            Assert.That(_instance.transform.childCount, Is.EqualTo(1));
            var anchor = _instance.transform.GetChild(0);
            Assert.That(anchor.name, Is.EqualTo("Anchor"));
            Assert.That(rope.StartAttachment.Point, Is.SameAs(anchor), "the reference points into the instance, not the asset");
            Assert.That(rope.StartAttachment.Kind, Is.EqualTo(RopeEndKind.Transform));
            Assert.That(rope.EndAttachment.Kind, Is.EqualTo(RopeEndKind.Free));
            Assert.That(rope.IsBuilt, Is.False, "edit mode: Awake does not build");

            var renderer = _instance.GetComponent<RopeMeshRenderer>();
            Assert.That(renderer, Is.Not.Null);
            Assert.That(renderer.RadialSegments, Is.EqualTo(12));
            Assert.That(_instance.GetComponent<MeshRenderer>().sharedMaterials.Length, Is.EqualTo(0), "materials are generated at the first render");
            Assert.That(_instance.GetComponent<MeshFilter>().sharedMesh, Is.Null);
        }

        [Test]
        public void PrefabRopeHangsWithItsWeightOnTheAnchor()
        {
            var rope = Instantiate();
            _instance.transform.position = new Vector3(0f, 5f, 0f);
            rope.Rebuild();
            Assert.That(rope.ParticleCount, Is.EqualTo(25));
            for (int step = 0; step < 200; step++) rope.Simulate(0.01f);

            float weight = rope.LinearDensity * rope.RestLength * G;
            Assert.That(weight, Is.EqualTo(1140f * Mathf_Pi * 0.008f * 0.008f * 2f * G).Within(1e-4f));
            Assert.That(rope.TopTension, Is.EqualTo(weight).Within(0.03f * weight), "μ·L·g");
            // Discrete statics of 24 segments: the top segment holds all but the pinned particle's half segment, the
            // bottom one only the free end's half segment.
            Assert.That(rope.TopTension, Is.EqualTo(weight * (1f - 0.5f / 24f)).Within(0.005f * weight));
            Assert.That(rope.BottomTension, Is.EqualTo(weight * 0.5f / 24f).Within(0.005f * weight));
            Assert.That(rope.GetParticlePosition(0).y, Is.EqualTo(5f).Within(1e-4f), "the top particle stays on the anchor");
            Assert.That(rope.GetParticlePosition(rope.ParticleCount - 1).y, Is.EqualTo(3f).Within(0.01f), "hangs its rest length below");

            var renderer = _instance.GetComponent<RopeMeshRenderer>();
            Assert.That(renderer.Render(1f), Is.True);
            Assert.That(renderer.Mesh.vertexCount, Is.GreaterThan(25 * 12));
            Assert.That(_instance.GetComponent<MeshFilter>().sharedMesh, Is.SameAs(renderer.Mesh));
        }

        const float Mathf_Pi = (float)System.Math.PI;
    }
}
