using System;
using System.IO;
using System.Linq;
using HookeRope.Editor;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's serialization and editor layer against Unity's documentation and reference source: which
    /// fields Unity serializes (Scripting Reference "SerializeField"), Object.Instantiate (clones by value, remaps
    /// references inside the clone, "(Clone)" names, Awake after the fields are set, placement overloads),
    /// SerializedObject/SerializedProperty (paths such as "m_Start.m_Point" and "m_Colliders.Array.data[0]", edits
    /// applied with Undo and OnValidate), the package's prefab loaded from its YAML with every field mapped,
    /// EditorApplication.ExecuteMenuItem, GameObjectUtility.SetParentAndAlign and Editor.CreateEditor.
    /// </summary>
    [TestFixture]
    public sealed class SerializationFactsTests
    {
        const string PrefabAssetPath = "Packages/com.hookerope.elastic-rope/Runtime/Prefabs/ElasticRope.prefab";
        FreshWorld _world;
        string _temp;

        [SetUp] public void SetUp() => _world = new FreshWorld();

        [TearDown]
        public void TearDown()
        {
            _world.Dispose();
            if (_temp != null && Directory.Exists(_temp)) Directory.Delete(_temp, true);
            _temp = null;
        }

        // ---- which fields are serialized ------------------------------------------------------------------------
        [Test]
        public void SerializedFieldsArePublicOrSerializeFieldOfSerializableTypesBaseClassFirst()
        {
            var names = SerializedLayout.Of(typeof(SerializationProbe)).Members.Select(m => m.Name).ToArray();
            Assert.That(names, Is.EqualTo(new[]
            {
                "m_BaseValue", "speed", "m_Count", "m_Mode", "m_Label", "m_Offset", "m_Tint", "m_Mask", "m_End", "m_Pair", "m_Points", "m_Ends", "m_Other",
                "SpeedInAwake", "OnValidateCalls",
            }));
            Assert.That(SerializedLayout.Of(typeof(ProbeEnd)).Members.Select(m => m.Name), Is.EqualTo(new[] { "point", "m_Weight" }));
            Assert.That(SerializedLayout.Of(typeof(ElasticRope)).Members.Count, Is.EqualTo(47), "33 + the 8 fields of the material law and the 5 of the drag (issue 15) + the Gauss–Seidel kernel (issue 18)");
        }

        // ---- Object.Instantiate ---------------------------------------------------------------------------------
        static (GameObject Root, SerializationProbe Probe, Transform Hand, GameObject Outside) Rig()
        {
            var outside = new GameObject("Outside");
            var root = new GameObject("Rig");
            var hand = new GameObject("Hand").transform;
            hand.SetParent(root.transform, false);
            hand.localPosition = new Vector3(0f, 1f, 0f);
            var probe = root.AddComponent<SerializationProbe>();
            probe.speed = 4f;
            probe.Count = 12;
            probe.Mode = ProbeMode.C;
            probe.Label = "left";
            probe.Offset = new Vector3(0.5f, 0f, -2f);
            probe.Mask = 1 << 3;
            probe.End.point = hand;
            probe.End.Weight = 2.5f;
            probe.End.runtimeTag = 99;
            probe.Pair = new ProbePair { count = 6, offset = new Vector3(7f, 8f, 9f) };
            probe.Points = new[] { hand, outside.transform };
            probe.Ends.Add(new ProbeEnd { point = root.transform, Weight = 3f });
            probe.Other = outside;
            probe.runtimeCount = 50;
            probe.Private = 90;
            probe.Property = 40;
            return (root, probe, hand, outside);
        }

        [Test]
        public void InstantiateCopiesSerializedValuesAndRemapsReferencesIntoTheClone()
        {
            var (root, probe, hand, outside) = Rig();
            var clone = Object.Instantiate(root);
            var copy = clone.GetComponent<SerializationProbe>();
            var cloneHand = clone.transform.GetChild(0);

            Assert.That(clone.name, Is.EqualTo("Rig(Clone)"));
            Assert.That(cloneHand.name, Is.EqualTo("Hand"), "only the root gets (Clone)");
            Assert.That(cloneHand, Is.Not.SameAs(hand));
            Assert.That(cloneHand.localPosition.y, Is.EqualTo(1f));
            Assert.That(copy.speed, Is.EqualTo(4f));
            Assert.That(copy.Count, Is.EqualTo(12));
            Assert.That(copy.Mode, Is.EqualTo(ProbeMode.C));
            Assert.That(copy.Label, Is.EqualTo("left"));
            Assert.That(copy.Offset.z, Is.EqualTo(-2f));
            Assert.That(copy.Mask.value, Is.EqualTo(8));
            Assert.That(copy.Pair.count, Is.EqualTo(6));
            Assert.That(copy.Pair.offset.y, Is.EqualTo(8f));

            Assert.That(copy.End, Is.Not.SameAs(probe.End), "[Serializable] classes are copied by value");
            Assert.That(copy.End.Weight, Is.EqualTo(2.5f));
            Assert.That(copy.End.point, Is.SameAs(cloneHand), "a reference into the cloned hierarchy points at the clone");
            Assert.That(copy.Points, Is.Not.SameAs(probe.Points));
            Assert.That(copy.Points[0], Is.SameAs(cloneHand));
            Assert.That(copy.Points[1], Is.SameAs(outside.transform), "a reference outside the hierarchy is kept");
            Assert.That(copy.Other, Is.SameAs(outside));
            Assert.That(copy.Ends.Count, Is.EqualTo(1));
            Assert.That(copy.Ends[0], Is.Not.SameAs(probe.Ends[0]));
            Assert.That(copy.Ends[0].point, Is.SameAs(clone.transform));
            Assert.That(copy.Ends[0].Weight, Is.EqualTo(3f));

            copy.End.Weight = 9f;
            copy.Points[0] = null;
            Assert.That(probe.End.Weight, Is.EqualTo(2.5f), "the copy is independent");
            Assert.That(probe.Points[0], Is.SameAs(hand));
        }

        [Test]
        public void InstantiateLeavesFieldsUnitySkipsAtTheirConstructorValues()
        {
            var (root, _, _, _) = Rig();
            var copy = Object.Instantiate(root).GetComponent<SerializationProbe>();
            Assert.That(copy.runtimeCount, Is.EqualTo(5), "[NonSerialized]");
            Assert.That(copy.Private, Is.EqualTo(9), "private without [SerializeField]");
            Assert.That(copy.Property, Is.EqualTo(4), "properties are not serialized");
            Assert.That(copy.End.runtimeTag, Is.EqualTo(7), "[NonSerialized] inside a [Serializable] class");
        }

        [Test]
        public void InstantiateSendsAwakeOnlyAfterEveryFieldIsSet()
        {
            var (root, probe, _, _) = Rig();
            Assert.That(probe.SpeedInAwake, Is.EqualTo(1f), "the original's Awake ran inside AddComponent ([ExecuteAlways])");
            var copy = Object.Instantiate(root).GetComponent<SerializationProbe>();
            Assert.That(copy.SpeedInAwake, Is.EqualTo(4f));
        }

        [Test]
        public void InstantiatedRopeIsBuiltInPlayModeFromTheCopiedSettings()
        {
            World.IsPlaying = true;
            var go = new GameObject("Rope", typeof(ElasticRope));
            var rope = go.GetComponent<ElasticRope>();
            Assert.That(rope.ParticleCount, Is.EqualTo(25), "Awake built the default 24 segments");
            rope.SegmentCount = 10;
            var copy = Object.Instantiate(rope);
            Assert.That(copy, Is.Not.SameAs(rope));
            Assert.That(copy.gameObject.name, Is.EqualTo("Rope(Clone)"));
            Assert.That(copy.ParticleCount, Is.EqualTo(11), "Awake of the clone saw the copied segment count");
            Assert.That(World.Live<ElasticRope>().Count(), Is.EqualTo(2));
        }

        [Test]
        public void InstantiatePlacesTheCloneAsDocumented()
        {
            var parent = new GameObject("Parent").transform;
            parent.position = new Vector3(10f, 0f, 0f);
            var holder = new GameObject("Holder").transform;
            holder.position = new Vector3(0f, 5f, 0f);
            var original = new GameObject("Original").transform;
            original.SetParent(holder, false);
            original.localPosition = new Vector3(1f, 0f, 0f);

            var free = Object.Instantiate(original.gameObject);
            Assert.That(free.transform.parent, Is.Null, "no parent by default");
            Assert.That(free.transform.position.y, Is.EqualTo(5f), "the original's world position");

            var local = Object.Instantiate(original.gameObject, parent);
            Assert.That(local.transform.parent, Is.SameAs(parent));
            Assert.That(local.transform.localPosition.x, Is.EqualTo(1f), "the original's local position under the new parent");

            var world = Object.Instantiate(original.gameObject, parent, true);
            Assert.That(world.transform.position.x, Is.EqualTo(1f).Within(1e-5f));
            Assert.That(world.transform.position.y, Is.EqualTo(5f).Within(1e-5f), "instantiateInWorldSpace keeps the world position");

            var posed = Object.Instantiate(original.gameObject, new Vector3(0f, 0f, 3f), Quaternion.identity);
            Assert.That(posed.transform.position.z, Is.EqualTo(3f));
            Assert.That(posed.transform.parent, Is.Null);

            Assert.Throws<ArgumentException>(() => Object.Instantiate((Object)null));
        }

        [Test]
        public void InstantiateDoesNotCopyRuntimeListenersOfUnityEvents()
        {
            var rope = new GameObject("Rope").AddComponent<ElasticRope>();
            int calls = 0;
            float tension = 0f;
            UnityEngine.Events.UnityAction<Vector3, float> listener = (at, t) => { calls++; tension = t; };
            rope.OnBreak.AddListener(listener);
            rope.OnBreak.Invoke(new Vector3(0f, 1f, 0f), 40f);
            Assert.That(calls, Is.EqualTo(1));
            Assert.That(tension, Is.EqualTo(40f));

            var copy = Object.Instantiate(rope);
            Assert.That(copy.OnBreak, Is.Not.SameAs(rope.OnBreak));
            copy.OnBreak.Invoke(Vector3.zero, 1f);
            Assert.That(calls, Is.EqualTo(1), "listeners added from code are not serialized, so not cloned");
            rope.OnBreak.RemoveListener(listener);
            rope.OnBreak.Invoke(Vector3.zero, 2f);
            Assert.That(calls, Is.EqualTo(1));
        }

        [Test]
        public void ScriptableObjectsGetAwakeAndOnEnableInEditModeAndCloneByValue()
        {
            var asset = ScriptableObject.CreateInstance<ProbeAsset>();
            Assert.That(asset.Awakes, Is.EqualTo(1));
            Assert.That(asset.Enables, Is.EqualTo(1));
            asset.name = "Settings";
            asset.value = 3f;
            var copy = Object.Instantiate(asset);
            Assert.That(copy.name, Is.EqualTo("Settings(Clone)"));
            Assert.That(copy.value, Is.EqualTo(3f));
            Assert.That(copy.Awakes, Is.EqualTo(1));
            Assert.Throws<ArgumentException>(() => Object.Instantiate(asset, Vector3.zero, Quaternion.identity));
            Object.DestroyImmediate(asset);
            Assert.That(asset.Disables, Is.EqualTo(1));
            Assert.That(asset.Destroys, Is.EqualTo(1));
            Assert.That(asset == null, Is.True);
            Object.DestroyImmediate(copy);
        }

        // ---- SerializedObject / SerializedProperty --------------------------------------------------------------
        [Test]
        public void SerializedObjectEditIsWrittenOnApplyWithUndoAndOnValidate()
        {
            var rope = new GameObject("Rope").AddComponent<ElasticRope>();
            var probe = rope.gameObject.AddComponent<SerializationProbe>();
            var so = new SerializedObject(rope);
            so.FindProperty("m_RestLength").floatValue = 3.5f;
            Assert.That(rope.RestLength, Is.EqualTo(2f), "edits stay in the SerializedObject until applied");
            Assert.That(so.hasModifiedProperties, Is.True);
            int undo = UndoLog.Entries.Count;

            Assert.That(so.ApplyModifiedProperties(), Is.True);
            Assert.That(rope.RestLength, Is.EqualTo(3.5f));
            Assert.That(UndoLog.Entries.Count, Is.EqualTo(undo + 1));
            Assert.That(UndoLog.Entries[undo].What, Is.EqualTo(UndoLog.Kind.ModifiedProperties));
            Assert.That(so.ApplyModifiedProperties(), Is.False, "nothing left to apply");

            so.FindProperty("m_Radius").floatValue = -1f;
            so.ApplyModifiedPropertiesWithoutUndo();
            Assert.That(rope.Radius, Is.EqualTo(RopeParameters.Radius.Default), "OnValidate reset the applied value (at or below the exclusive minimum) to the table default");
            Assert.That(UndoLog.Entries.Count, Is.EqualTo(undo + 1), "WithoutUndo records nothing");

            var probeObject = new SerializedObject(probe);
            int calls = probe.OnValidateCalls;
            probeObject.FindProperty("m_Count").intValue = -4;
            probeObject.ApplyModifiedProperties();
            Assert.That(probe.OnValidateCalls, Is.EqualTo(calls + 1));
            Assert.That(probe.Count, Is.EqualTo(0));
            Assert.That(probeObject.FindProperty("m_Count").intValue, Is.EqualTo(-4), "the SerializedObject sees OnValidate's change only after Update()");
            probeObject.Update();
            Assert.That(probeObject.FindProperty("m_Count").intValue, Is.EqualTo(0));
        }

        [Test]
        public void FindPropertyUsesUnitysPathsForNestedFieldsArraysAndComponents()
        {
            var rope = new GameObject("Rope").AddComponent<ElasticRope>();
            var anchor = new GameObject("Anchor").transform;
            rope.StartAttachment.Point = anchor;
            var so = new SerializedObject(rope);

            var point = so.FindProperty("m_Start.m_Point");
            Assert.That(point.name, Is.EqualTo("m_Point"));
            Assert.That(point.propertyPath, Is.EqualTo("m_Start.m_Point"));
            Assert.That(point.propertyType, Is.EqualTo(SerializedPropertyType.ObjectReference));
            Assert.That(point.objectReferenceValue, Is.SameAs(anchor));
            Assert.That(so.FindProperty("m_Start").FindPropertyRelative("m_Body").propertyType, Is.EqualTo(SerializedPropertyType.ObjectReference));
            Assert.That(so.FindProperty("m_Start").propertyType, Is.EqualTo(SerializedPropertyType.Generic));

            var colliders = so.FindProperty("m_Colliders");
            Assert.That(colliders.isArray, Is.True);
            Assert.That(colliders.arraySize, Is.EqualTo(0));
            var size = so.FindProperty("m_Colliders.Array.size");
            Assert.That(size.propertyType, Is.EqualTo(SerializedPropertyType.ArraySize));
            Assert.That(size.name, Is.EqualTo("size"));
            Assert.That(so.FindProperty("m_Colliders.Array.data[0]"), Is.Null, "no element 0 in an empty array");
            size.intValue = 2;
            var element = so.FindProperty("m_Colliders.Array.data[1]");
            Assert.That(element.name, Is.EqualTo("data"));
            Assert.That(element.propertyType, Is.EqualTo(SerializedPropertyType.ObjectReference));
            Assert.That(colliders.GetArrayElementAtIndex(1).propertyPath, Is.EqualTo("m_Colliders.Array.data[1]"));
            var sphere = new GameObject("Ball").AddComponent<SphereCollider>();
            element.objectReferenceValue = sphere;
            so.ApplyModifiedProperties();
            Assert.That(rope.Colliders.Length, Is.EqualTo(2));
            Assert.That(rope.Colliders[1], Is.SameAs(sphere));

            Assert.That(so.FindProperty("m_Gravity").vector3Value.y, Is.EqualTo(-9.81f));
            Assert.That(so.FindProperty("m_Gravity.y").floatValue, Is.EqualTo(-9.81f));
            Assert.That(so.FindProperty("m_Gravity.y").propertyType, Is.EqualTo(SerializedPropertyType.Float));
            Assert.That(so.FindProperty("m_CollisionLayers").propertyType, Is.EqualTo(SerializedPropertyType.LayerMask));
            Assert.That(so.FindProperty("m_CollisionLayers").intValue, Is.EqualTo(-1));
            var solver = so.FindProperty("m_Solver");
            Assert.That(solver.propertyType, Is.EqualTo(SerializedPropertyType.Enum));
            Assert.That(solver.enumNames[solver.enumValueIndex], Is.EqualTo("ExactChain"));
            Assert.That(so.FindProperty("m_OnBreak.m_PersistentCalls.m_Calls.Array.size").intValue, Is.EqualTo(0));
            Assert.That(so.FindProperty("m_Fracture").boolValue, Is.True);
            Assert.That(so.FindProperty("m_NoSuchField"), Is.Null);
            Assert.That(so.FindProperty("_rope"), Is.Null, "not a serialized field");

            LogAssert.Expect(LogType.Error, "type is not a supported float value");
            Assert.That(so.FindProperty("m_SegmentCount").floatValue, Is.EqualTo(0f));
        }

        [Test]
        public void MultiObjectEditingReportsDifferentValuesAndWritesAllTargets()
        {
            var a = new GameObject("A").AddComponent<ElasticRope>();
            var b = new GameObject("B").AddComponent<ElasticRope>();
            b.Friction = 0.6f;
            var so = new SerializedObject(new Object[] { a, b });
            Assert.That(so.isEditingMultipleObjects, Is.True);
            Assert.That(so.FindProperty("m_Friction").hasMultipleDifferentValues, Is.True);
            Assert.That(so.FindProperty("m_Density").hasMultipleDifferentValues, Is.False);
            so.FindProperty("m_Friction").floatValue = 1.2f;
            so.ApplyModifiedProperties();
            Assert.That(a.Friction, Is.EqualTo(1.2f));
            Assert.That(b.Friction, Is.EqualTo(1.2f));
        }

        [Test]
        public void CreateEditorRunsTheInspectorsOnEnable()
        {
            var rope = new GameObject("Rope").AddComponent<ElasticRope>();
            var editor = UnityEditor.Editor.CreateEditor(rope);
            Assert.That(editor.GetType().Name, Is.EqualTo("ElasticRopeEditor"));
            Assert.That(editor.target, Is.SameAs(rope));
            Assert.That(editor.serializedObject.targetObject, Is.SameAs(rope));
            Assert.Throws<NotSupportedException>(() => editor.OnInspectorGUI(), "IMGUI is outside the stand-in");
            Object.DestroyImmediate(editor);
        }

        // ---- prefab assets ----------------------------------------------------------------------------------------
        [Test]
        public void PackagePrefabLoadsWithEverySerializedFieldMapped()
        {
            var prefab = AssetDatabase.LoadAssetAtPath<GameObject>(PrefabAssetPath);
            Assert.That(prefab, Is.Not.Null);
            var asset = PrefabAssets.Of(prefab);
            Assert.That(asset.MissingFields, Is.Empty, "the prefab names every serialized field of its scripts");
            Assert.That(prefab.name, Is.EqualTo("Elastic Rope"));
            Assert.That(prefab.GetComponents<Component>().Select(c => c.GetType().Name),
                Is.EqualTo(new[] { "Transform", "MeshFilter", "MeshRenderer", "ElasticRope", "RopeMeshRenderer" }));
            var rope = prefab.GetComponent<ElasticRope>();
            Assert.That(rope.YoungsModulus, Is.EqualTo(1.5e8f));
            Assert.That(rope.SegmentCount, Is.EqualTo(24));
            Assert.That(rope.StartAttachment.Point, Is.SameAs(prefab.transform.GetChild(0)));
            Assert.That(rope.CollisionMode, Is.EqualTo(RopeCollisionMode.Off));
            Assert.That(AssetDatabase.LoadAssetAtPath<ElasticRope>(PrefabAssetPath), Is.SameAs(rope), "the first object of the asked type");
            Assert.That(AssetDatabase.LoadAssetAtPath<GameObject>(PrefabAssetPath), Is.SameAs(prefab), "loaded once");
            Assert.That(World.Live<ElasticRope>(), Is.Empty, "an asset is not in the scene");
            Assert.That(rope.IsBuilt, Is.False, "no Awake for assets");
            Assert.That(prefab.activeSelf, Is.True, "a prefab asset keeps its own active state");
            Assert.That(prefab.activeInHierarchy, Is.False, "an asset is in no scene hierarchy");
            LogAssert.Expect(LogType.Error, "Destroying assets is not permitted to avoid data loss.\nIf you really want to remove an asset use DestroyImmediate (theObject, true);");
            Object.DestroyImmediate(prefab);
            Assert.That(prefab == null, Is.False, "assets are destroyed only with allowDestroyingAssets");
            Assert.That(AssetDatabase.LoadAssetAtPath<GameObject>("Packages/com.hookerope.elastic-rope/Runtime/Prefabs/Missing.prefab"), Is.Null);

            var instance = (GameObject)PrefabUtility.InstantiatePrefab(prefab);
            Assert.That(instance.name, Is.EqualTo("Elastic Rope"), "named as the prefab, not (Clone)");
            Assert.That(instance.GetComponent<ElasticRope>().StartAttachment.Point, Is.SameAs(instance.transform.GetChild(0)));
            Assert.That(World.Live<ElasticRope>().Count(), Is.EqualTo(1));
            Assert.That(Object.Instantiate(prefab).name, Is.EqualTo("Elastic Rope(Clone)"));
        }

        [TestCase("m_Friction", "m_Frictionn", "no field of that name")]
        [TestCase("m_Friction", "_rope", "does not serialize it")]
        [TestCase("m_Point", "m_Pointer", "no field of that name")]
        public void PrefabFieldThatMapsToNoSerializedFieldFailsNamingFileLineAndField(string field, string planted, string why)
        {
            string root = PackageFiles.FindPackage("com.hookerope.elastic-rope");
            _temp = Path.Combine(Path.GetTempPath(), "hookerope-prefab-" + Guid.NewGuid().ToString("N"));
            File.Copy(Path.Combine(root, "package.json"), Directory.CreateDirectory(_temp).FullName + "/package.json");
            foreach (string meta in Directory.GetFiles(Path.Combine(root, "Runtime"), "*.cs.meta", SearchOption.AllDirectories))
            {
                string target = Path.Combine(_temp, Path.GetRelativePath(root, meta));
                Directory.CreateDirectory(Path.GetDirectoryName(target));
                File.Copy(meta, target);
            }
            var lines = File.ReadAllLines(Path.Combine(root, "Runtime/Prefabs/ElasticRope.prefab"));
            int index = Array.FindIndex(lines, l => l.TrimStart().StartsWith(field + ":", StringComparison.Ordinal));
            lines[index] = lines[index].Replace(field + ":", planted + ":");
            string prefab = Path.Combine(_temp, "Runtime/Prefabs/ElasticRope.prefab");
            Directory.CreateDirectory(Path.GetDirectoryName(prefab));
            File.WriteAllLines(prefab, lines);

            var e = Assert.Throws<FormatException>(() => PrefabLoader.Load(prefab));
            Assert.That(e.Message, Does.StartWith(prefab + ":" + (index + 1) + ":"));
            Assert.That(e.Message, Does.Contain("'" + planted + "'"));
            Assert.That(e.Message, Does.Contain(why));
        }

        [Test]
        public void UnityYamlParserReadsUnitysBlockAndFlowStyles()
        {
            const string text = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!114 &7\nMonoBehaviour:\n  m_Name: 'it''s here'\n" +
                                "  m_List:\n  - a: {x: 1, y: -2.5, z: 0}\n    b: \"tab\\tbed\"\n  - a: {x: 0, y: 0, z: 0}\n    b: plain text\n  m_Empty: []\n  m_Value: 1e-3\n";
            var docs = UnityYamlParser.Parse(text, "probe.prefab");
            Assert.That(docs.Count, Is.EqualTo(1));
            Assert.That(docs[0].ClassId, Is.EqualTo(114));
            Assert.That(docs[0].FileId, Is.EqualTo(7));
            var body = docs[0].Body;
            Assert.That(((YamlScalar)body.Find("m_Name")).Value, Is.EqualTo("it's here"));
            var list = (YamlSequence)body.Find("m_List");
            Assert.That(list.Items.Count, Is.EqualTo(2));
            var first = (YamlMapping)list.Items[0];
            Assert.That(((YamlScalar)((YamlMapping)first.Find("a")).Find("y")).Value, Is.EqualTo("-2.5"));
            Assert.That(((YamlScalar)first.Find("b")).Value, Is.EqualTo("tab\tbed"));
            Assert.That(((YamlScalar)((YamlMapping)list.Items[1]).Find("b")).Value, Is.EqualTo("plain text"));
            Assert.That(((YamlSequence)body.Find("m_Empty")).Items, Is.Empty);
            Assert.That(body.Find("m_Value").Line, Is.EqualTo(12));
            var e = Assert.Throws<FormatException>(() => UnityYamlParser.Parse("--- !u!1 &1\nGameObject:\n  m_Name: a\n    m_Bad: b\n", "bad.prefab"));
            Assert.That(e.Message, Does.StartWith("bad.prefab:"));
        }

        // ---- menu, selection, parenting ----------------------------------------------------------------------
        [Test]
        public void ExecuteMenuItemRunsThePackagesCreateMenu()
        {
            int undo = UndoLog.Entries.Count;
            Assert.That(EditorApplication.ExecuteMenuItem(ElasticRopeMenu.MenuPath), Is.True);
            var created = Selection.activeGameObject;
            Assert.That(created, Is.Not.Null);
            Assert.That(created.name, Is.EqualTo("Elastic Rope"));
            Assert.That(Selection.activeTransform, Is.SameAs(created.transform));
            Assert.That(created.transform.parent, Is.Null, "the menu passes a MenuCommand with a null context");
            Assert.That(created.GetComponent<ElasticRope>().StartAttachment.Point.localPosition.x, Is.EqualTo(-0.8f));
            Assert.That(created.transform.childCount, Is.EqualTo(2));
            Assert.That(UndoLog.Entries.Count, Is.EqualTo(undo + 1));
            Assert.That(UndoLog.Entries[undo].What, Is.EqualTo(UndoLog.Kind.CreatedObject));
            Assert.That(UndoLog.Entries[undo].Name, Is.EqualTo("Create Elastic Rope"));
            Assert.That(UndoLog.Entries[undo].Target, Is.SameAs(created));

            LogAssert.Expect(LogType.Error, "ExecuteMenuItem failed because there is no menu named 'GameObject/No Such Item'");
            Assert.That(EditorApplication.ExecuteMenuItem("GameObject/No Such Item"), Is.False);
        }

        [Test]
        public void SetParentAndAlignResetsTheLocalPoseAndTakesTheParentsLayer()
        {
            var parent = new GameObject("Parent") { layer = 4 };
            parent.transform.position = new Vector3(3f, 0f, 0f);
            var child = new GameObject("Child");
            var grandChild = new GameObject("GrandChild");
            grandChild.transform.SetParent(child.transform, false);
            child.transform.position = new Vector3(0f, 7f, 0f);
            child.transform.localScale = new Vector3(2f, 2f, 2f);

            GameObjectUtility.SetParentAndAlign(child, null);
            Assert.That(child.transform.parent, Is.Null, "nothing happens without a parent");
            Assert.That(child.transform.position.y, Is.EqualTo(7f));

            GameObjectUtility.SetParentAndAlign(child, parent);
            Assert.That(child.transform.parent, Is.SameAs(parent.transform));
            Assert.That(child.transform.localPosition, Is.EqualTo(Vector3.zero));
            Assert.That(child.transform.localScale.x, Is.EqualTo(1f));
            Assert.That(child.layer, Is.EqualTo(4));
            Assert.That(grandChild.layer, Is.EqualTo(4));
        }

        [Test]
        public void SelectionForgetsDestroyedObjectsAndNeverReturnsAPrefabAssetsTransform()
        {
            var go = new GameObject("Picked");
            Selection.activeObject = go;
            Assert.That(Selection.activeTransform, Is.SameAs(go.transform));
            Object.DestroyImmediate(go);
            Assert.That(Selection.activeObject, Is.Null);

            var prefab = AssetDatabase.LoadAssetAtPath<GameObject>(PrefabAssetPath);
            Selection.activeObject = prefab;
            Assert.That(Selection.activeGameObject, Is.SameAs(prefab));
            Assert.That(Selection.activeTransform, Is.Null);
        }
    }
}
