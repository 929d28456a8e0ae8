using System;
using System.Collections.Generic;
using System.IO;
using UnityEngine;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: builds a prefab asset from its Unity YAML: GameObjects (name, layer, active, hide flags),
    /// Transforms (local position, rotation, scale and the child order of m_Children), MeshFilter (mesh),
    /// MeshRenderer (enabled, materials) and MonoBehaviours (script class from m_Script's guid via the package's
    /// .cs.meta files; every serialized value through <see cref="SerializedValueReader"/>). References inside the file
    /// are resolved, {fileID: 0} is null, Unity's built-in meshes and Default-Material map to the rendering
    /// stand-in's. The asset stays out of the scene and receives no Awake/OnEnable; like the Editor loading a
    /// prefab, the stand-in sends OnValidate to its scripts once. Anything it cannot map — an unknown class ID or
    /// field, a nested prefab, a reference to another asset — is an error naming the file, line and field.
    /// </summary>
    internal sealed class PrefabLoader
    {
        const int GameObjectClass = 1, TransformClass = 4, MeshRendererClass = 23, MeshFilterClass = 33, MonoBehaviourClass = 114;

        static readonly string[] PrefabLinks = { "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset" };
        static readonly HashSet<string> GameObjectKeys = Keys("m_ObjectHideFlags", "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset",
            "serializedVersion", "m_Component", "m_Layer", "m_Name", "m_TagString", "m_Icon", "m_NavMeshLayer", "m_StaticEditorFlags", "m_IsActive");
        static readonly HashSet<string> ComponentHeader = Keys("m_ObjectHideFlags", "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset", "m_GameObject");
        static readonly HashSet<string> TransformKeys = Keys("serializedVersion", "m_LocalRotation", "m_LocalPosition", "m_LocalScale",
            "m_ConstrainProportionsScale", "m_Children", "m_Father", "m_RootOrder", "m_LocalEulerAnglesHint");
        static readonly HashSet<string> MeshFilterKeys = Keys("m_Mesh");
        static readonly HashSet<string> MeshRendererKeys = Keys("m_Enabled", "m_Materials",
            // Lighting, probes, lightmapping, sorting and batching: no effect in the stand-in (it renders nothing).
            "m_CastShadows", "m_ReceiveShadows", "m_DynamicOccludee", "m_StaticShadowCaster", "m_MotionVectors", "m_LightProbeUsage",
            "m_ReflectionProbeUsage", "m_RayTracingMode", "m_RayTraceProcedural", "m_RenderingLayerMask", "m_RendererPriority",
            "m_StaticBatchInfo", "m_StaticBatchRoot", "m_ProbeAnchor", "m_LightProbeVolumeOverride", "m_ScaleInLightmap", "m_ReceiveGI",
            "m_PreserveUVs", "m_IgnoreNormalsForChartDetection", "m_ImportantGI", "m_StitchLightmapSeams", "m_SelectedEditorRenderState",
            "m_MinimumChartSize", "m_AutoUVMaxDistance", "m_AutoUVMaxAngle", "m_LightmapParameters", "m_SortingLayerID", "m_SortingLayer",
            "m_SortingOrder", "m_AdditionalVertexStreams", "m_LightmapIndex", "m_LightmapTilingOffset", "m_LightmapIndexDynamic",
            "m_LightmapTilingOffsetDynamic", "m_EnlightenVertexStream");
        static readonly HashSet<string> MonoBehaviourHeader = Keys("m_ObjectHideFlags", "m_CorrespondingSourceObject", "m_PrefabInstance",
            "m_PrefabAsset", "m_GameObject", "m_Enabled", "m_EditorHideFlags", "m_Script", "m_Name", "m_EditorClassIdentifier");

        readonly string m_File;
        readonly string m_PackageRoot;
        readonly Dictionary<long, UnityYamlDocument> m_Documents = new Dictionary<long, UnityYamlDocument>();
        readonly Dictionary<long, Object> m_Objects = new Dictionary<long, Object>();
        readonly List<Object> m_InOrder = new List<Object>();
        readonly SerializedValueReader m_Reader;

        PrefabLoader(string file)
        {
            m_File = file;
            m_PackageRoot = PackageFiles.RootOf(file);
            m_Reader = new SerializedValueReader(file, Resolve);
        }

        /// <summary>Loads the prefab at <paramref name="file"/> (a file system path inside a package).</summary>
        internal static PrefabAsset Load(string file)
        {
            var documents = UnityYamlParser.Parse(File.ReadAllText(file), file);
            return new PrefabLoader(file).Build(documents);
        }

        PrefabAsset Build(List<UnityYamlDocument> documents)
        {
            var gameObjects = new List<UnityYamlDocument>();
            foreach (var doc in documents)
            {
                if (m_Documents.ContainsKey(doc.FileId)) throw YamlError.At(m_File, doc.Line, "duplicate object &" + doc.FileId);
                CheckSupported(doc);
                m_Documents[doc.FileId] = doc;
                if (doc.ClassId == GameObjectClass) gameObjects.Add(doc);
            }
            var created = new List<(UnityYamlDocument Doc, GameObject Go)>();
            foreach (var doc in gameObjects) created.Add((doc, CreateGameObject(doc)));
            var claimed = new HashSet<long>();
            foreach (var (doc, go) in created) CreateComponents(doc, go, claimed);
            foreach (var doc in documents)
                if (doc.ClassId != GameObjectClass && !claimed.Contains(doc.FileId))
                    throw YamlError.At(m_File, doc.Line, doc.TypeName + " &" + doc.FileId + " is not listed in any GameObject's m_Component");
            var root = BuildHierarchy(documents);
            foreach (var doc in documents) ReadComponent(doc);
            foreach (var (doc, go) in created) ReadGameObject(doc, go);

            SceneHooks.MarkAsset(root);
            var behaviours = new List<MonoBehaviour>();
            foreach (var go in SceneHooks.Hierarchy(root)) go.CollectComponents(behaviours);
            foreach (var behaviour in behaviours) Messages.Send(behaviour, "OnValidate");
            return new PrefabAsset(m_File, root, m_InOrder, m_Reader.MissingFields);
        }

        void CheckSupported(UnityYamlDocument doc)
        {
            if (doc.Stripped) throw YamlError.At(m_File, doc.Line, "stripped object &" + doc.FileId + " (part of a nested prefab): nested prefabs are not supported by the stand-in");
            string expected;
            switch (doc.ClassId)
            {
                case GameObjectClass: expected = "GameObject"; break;
                case TransformClass: expected = "Transform"; break;
                case MeshRendererClass: expected = "MeshRenderer"; break;
                case MeshFilterClass: expected = "MeshFilter"; break;
                case MonoBehaviourClass: expected = "MonoBehaviour"; break;
                default:
                    throw YamlError.At(m_File, doc.Line, doc.TypeName + " (class ID " + doc.ClassId + ") is not supported by the stand-in's prefab loader " +
                                                         "(it reads GameObject, Transform, MeshFilter, MeshRenderer and MonoBehaviour)");
            }
            if (doc.TypeName != expected) throw YamlError.At(m_File, doc.Line, "class ID " + doc.ClassId + " is a " + expected + ", not a " + doc.TypeName);
            foreach (string link in PrefabLinks)
            {
                var node = doc.Body.Find(link);
                if (node != null && !IsNull(node))
                    throw YamlError.At(m_File, node.Line, link + " of &" + doc.FileId + " links to another prefab: nested prefabs and variants are not supported by the stand-in");
            }
        }

        GameObject CreateGameObject(UnityYamlDocument doc)
        {
            CheckKeys(doc, GameObjectKeys, null);
            string name = (string)Value(doc, "m_Name", typeof(string)) ?? "";
            bool active = (bool?)Value(doc, "m_IsActive", typeof(bool)) ?? true;
            var go = SceneHooks.NewDetached(name, active);
            m_Objects[doc.FileId] = go;
            m_InOrder.Add(go);
            return go;
        }

        void CreateComponents(UnityYamlDocument doc, GameObject go, HashSet<long> claimed)
        {
            var list = doc.Body.Find("m_Component") as YamlSequence ?? throw YamlError.At(m_File, doc.Line, "GameObject &" + doc.FileId + " has no m_Component list");
            for (int i = 0; i < list.Items.Count; i++)
            {
                var item = list.Items[i] as YamlMapping;
                var reference = item?.Find("component") as YamlMapping;
                if (reference == null || item.Entries.Count != 1) throw YamlError.At(m_File, list.Items[i].Line, "m_Component items must be '- component: {fileID: …}'");
                long id = FileId(reference, "m_Component");
                if (!m_Documents.TryGetValue(id, out var component) || component.ClassId == GameObjectClass)
                    throw YamlError.At(m_File, reference.Line, "m_Component of '" + go.name + "' refers to &" + id + ", which is not a component in this file");
                if (!claimed.Add(id)) throw YamlError.At(m_File, reference.Line, "component &" + id + " is listed twice");
                var owner = component.Body.Find("m_GameObject") as YamlMapping;
                if (owner == null || FileId(owner, "m_GameObject") != doc.FileId)
                    throw YamlError.At(m_File, component.Line, component.TypeName + " &" + id + " names another m_GameObject than '" + go.name + "', which lists it");
                if ((i == 0) != (component.ClassId == TransformClass))
                    throw YamlError.At(m_File, reference.Line, "the Transform must be the first (and only the first) component of '" + go.name + "'");
                Component created = i == 0 ? go.transform : AddComponent(go, ComponentType(component), component.Line);
                m_Objects[id] = created;
                m_InOrder.Add(created);
            }
        }

        Type ComponentType(UnityYamlDocument doc)
        {
            if (doc.ClassId == MeshFilterClass) return typeof(MeshFilter);
            if (doc.ClassId == MeshRendererClass) return typeof(MeshRenderer);
            var script = doc.Body.Find("m_Script") as YamlMapping ?? throw YamlError.At(m_File, doc.Line, "MonoBehaviour &" + doc.FileId + " has no m_Script");
            string guid = (script.Find("guid") as YamlScalar)?.Value;
            if (guid == null || FileId(script, "m_Script") != 11500000)
                throw YamlError.At(m_File, script.Line, "m_Script of &" + doc.FileId + " is not a script reference {fileID: 11500000, guid: …}");
            string file = m_PackageRoot != null ? PackageScripts.ScriptFile(m_PackageRoot, guid) : null;
            if (file == null) throw YamlError.At(m_File, script.Line, "m_Script guid " + guid + " is no .cs file of the package at " + (m_PackageRoot ?? "(no package.json above the file)"));
            string className = Path.GetFileNameWithoutExtension(file);
            var classes = PackageScripts.Classes(className);
            if (classes.Count != 1)
                throw YamlError.At(m_File, script.Line, "m_Script guid " + guid + " is " + file + ", whose class " + className +
                                                        (classes.Count == 0 ? " is not loaded" : " is ambiguous: " + string.Join(", ", classes)));
            if (!typeof(MonoBehaviour).IsAssignableFrom(classes[0]))
                throw YamlError.At(m_File, script.Line, "m_Script of &" + doc.FileId + " is " + classes[0].FullName + ", not a MonoBehaviour");
            return classes[0];
        }

        /// <summary>Adds <paramref name="type"/>, or takes the one [RequireComponent] already added for an earlier component.</summary>
        Component AddComponent(GameObject go, Type type, int line)
        {
            foreach (var existing in go.ComponentList)
                if (existing.GetType() == type && !m_InOrder.Contains(existing)) return existing;
            return go.AddComponent(type) ?? throw YamlError.At(m_File, line, "cannot add a " + type.Name + " to '" + go.name + "'");
        }

        GameObject BuildHierarchy(List<UnityYamlDocument> documents)
        {
            Transform root = null;
            foreach (var doc in documents)
            {
                if (doc.ClassId != TransformClass) continue;
                CheckKeys(doc, TransformKeys, ComponentHeader);
                var transform = (Transform)m_Objects[doc.FileId];
                transform.localPosition = (Vector3)(Value(doc, "m_LocalPosition", typeof(Vector3)) ?? Vector3.zero);
                transform.localRotation = (Quaternion)(Value(doc, "m_LocalRotation", typeof(Quaternion)) ?? Quaternion.identity);
                transform.localScale = (Vector3)(Value(doc, "m_LocalScale", typeof(Vector3)) ?? Vector3.one);
                var father = (Transform)Value(doc, "m_Father", typeof(Transform));
                if (father == null)
                {
                    if (root != null) throw YamlError.At(m_File, doc.Line, "a prefab has one root Transform; '" + root.name + "' and '" + transform.name + "' both have no m_Father");
                    root = transform;
                }
                var children = (Transform[])(Value(doc, "m_Children", typeof(Transform[])) ?? Array.Empty<Transform>());
                foreach (var child in children)
                {
                    long childId = IdOf(child);
                    if ((Transform)Value(m_Documents[childId], "m_Father", typeof(Transform)) != transform)
                        throw YamlError.At(m_File, doc.Body.Find("m_Children").Line, "'" + child.name + "' is a child of '" + transform.name + "' whose m_Father is not that Transform");
                    child.SetParent(transform, false);
                }
            }
            if (root == null) throw YamlError.At(m_File, 1, "no root Transform (one without m_Father) in the prefab");
            foreach (var doc in documents)
                if (doc.ClassId == TransformClass && (Transform)m_Objects[doc.FileId] != root && ((Transform)m_Objects[doc.FileId]).parent == null)
                    throw YamlError.At(m_File, doc.Line, "Transform &" + doc.FileId + " has an m_Father that does not list it in m_Children");
            return root.gameObject;
        }

        void ReadComponent(UnityYamlDocument doc)
        {
            switch (doc.ClassId)
            {
                case MeshFilterClass:
                    CheckKeys(doc, MeshFilterKeys, ComponentHeader);
                    ((MeshFilter)m_Objects[doc.FileId]).sharedMesh = (Mesh)Value(doc, "m_Mesh", typeof(Mesh));
                    return;
                case MeshRendererClass:
                {
                    CheckKeys(doc, MeshRendererKeys, ComponentHeader);
                    var renderer = (MeshRenderer)m_Objects[doc.FileId];
                    renderer.sharedMaterials = (Material[])(Value(doc, "m_Materials", typeof(Material[])) ?? Array.Empty<Material>());
                    renderer.enabled = (bool?)Value(doc, "m_Enabled", typeof(bool)) ?? true;
                    ApplyHideFlags(doc, renderer);
                    return;
                }
                case MonoBehaviourClass:
                {
                    var behaviour = (MonoBehaviour)m_Objects[doc.FileId];
                    m_Reader.ReadFields(behaviour, doc.Body, MonoBehaviourHeader, behaviour.GetType().Name);
                    behaviour.enabled = (bool?)Value(doc, "m_Enabled", typeof(bool)) ?? true;
                    ApplyHideFlags(doc, behaviour);
                    return;
                }
            }
        }

        void ReadGameObject(UnityYamlDocument doc, GameObject go)
        {
            int layer = (int?)Value(doc, "m_Layer", typeof(int)) ?? 0;
            if (layer < 0 || layer > 31) throw YamlError.At(m_File, doc.Body.Find("m_Layer").Line, "m_Layer of '" + go.name + "' must be 0…31");
            go.layer = layer;
            string tag = (string)Value(doc, "m_TagString", typeof(string)) ?? "Untagged";
            // Unity's built-in tags (GameObject.BuiltInTags); a project tag would need the TagManager, which is not modelled
            if (System.Array.IndexOf(GameObject.BuiltInTags, tag) < 0)
                throw YamlError.At(m_File, doc.Body.Find("m_TagString").Line,
                    "m_TagString of '" + go.name + "' is " + tag + ": only Unity's built-in tags are modelled (the project's TagManager is not)");
            go.tag = tag;
            ApplyHideFlags(doc, go);
        }

        void ApplyHideFlags(UnityYamlDocument doc, Object target)
        {
            int? flags = (int?)Value(doc, "m_ObjectHideFlags", typeof(int));
            if (flags.HasValue) target.hideFlags = (HideFlags)flags.Value;
        }

        // ---- values and references ----------------------------------------------------------------------------
        object Value(UnityYamlDocument doc, string key, Type type)
        {
            var node = doc.Body.Find(key);
            return node == null ? null : m_Reader.ReadValue(node, type, doc.TypeName + " &" + doc.FileId + "." + key);
        }

        Object Resolve(YamlMapping reference, Type expected, string path)
        {
            foreach (var entry in reference.Entries)
                if (entry.Key != "fileID" && entry.Key != "guid" && entry.Key != "type")
                    throw YamlError.At(m_File, entry.Line, "field '" + entry.Key + "' of " + path + " does not map: an object reference has fileID, guid and type");
            long id = FileId(reference, path);
            if (id == 0) return null;
            string guid = (reference.Find("guid") as YamlScalar)?.Value;
            Object found;
            if (string.IsNullOrEmpty(guid))
            {
                if (!m_Objects.TryGetValue(id, out found))
                    throw YamlError.At(m_File, reference.Line, path + " refers to &" + id + ", which is no GameObject or component in this file");
            }
            else
            {
                found = BuiltinAssets.Find(guid, id);
                if (found == null)
                    throw YamlError.At(m_File, reference.Line, path + " refers to another asset {fileID: " + id + ", guid: " + guid + "}: the stand-in resolves only " +
                                                               "objects inside the prefab, Unity's built-in primitive meshes and Default-Material");
            }
            if (!expected.IsInstanceOfType(found))
                throw YamlError.At(m_File, reference.Line, path + " expects a " + expected.Name + " but &" + id + " is a " + found.GetType().Name);
            return found;
        }

        long FileId(YamlMapping reference, string path)
        {
            var node = reference.Find("fileID") as YamlScalar ?? throw YamlError.At(m_File, reference.Line, path + " is not an object reference {fileID: …}");
            if (!long.TryParse(node.Value, System.Globalization.NumberStyles.Integer, System.Globalization.CultureInfo.InvariantCulture, out long id))
                throw YamlError.At(m_File, node.Line, path + " has a malformed fileID '" + node.Value + "'");
            return id;
        }

        long IdOf(Object o)
        {
            foreach (var pair in m_Objects)
                if (ReferenceEquals(pair.Value, o)) return pair.Key;
            return 0;
        }

        static bool IsNull(YamlNode node) => node is YamlMapping map && map.Find("fileID") is YamlScalar id && id.Value == "0";

        void CheckKeys(UnityYamlDocument doc, HashSet<string> keys, HashSet<string> header)
        {
            foreach (var entry in doc.Body.Entries)
                if (!keys.Contains(entry.Key) && (header == null || !header.Contains(entry.Key)))
                    throw YamlError.At(m_File, entry.Line, "field '" + entry.Key + "' of " + doc.TypeName + " &" + doc.FileId +
                                                           " does not map: the stand-in's prefab loader knows no such " + doc.TypeName + " field");
        }

        static HashSet<string> Keys(params string[] keys) => new HashSet<string>(keys, StringComparer.Ordinal);
    }
}
