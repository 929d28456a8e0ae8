using System.Collections.Generic;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// Which Unity 2022.3 module implements each UnityEngine / UnityEditor type the package may use, and which
    /// built-in package ("com.unity.modules.*", version 1.0.0 in 2022.3) switches that module on. The single place to
    /// update when the package starts using a new Unity type: <see cref="ModuleDependencyTests"/> fails on any used
    /// type missing here. Source: the Unity 2022.3 Scripting Reference page of each type ("Implemented in:
    /// UnityEngine.XModule") and the built-in package pages of the 2022.3 Manual (com.unity.modules.x → Scripting API
    /// UnityEngine.XModule); the source per module is in <see cref="Module.Source"/>.
    /// Covers every type of the stand-in (Tools~/Unity/UnityEngine, Tools~/Unity/UnityEditor), whether used or not.
    /// </summary>
    static class UnityModuleTable
    {
        /// <summary>A Unity module assembly and the built-in package that enables it (null: always present).</summary>
        public sealed class Module
        {
            public Module(string assembly, string package, string source)
            {
                Assembly = assembly;
                Package = package;
                Source = source;
            }

            public string Assembly { get; }
            public string Package { get; }
            public string Source { get; }
        }

        /// <summary>Version of every built-in module package in Unity 2022.3 ("fixed to a single version").</summary>
        public const string BuiltInModuleVersion = "1.0.0";

        public static readonly Module CoreModule = new Module("UnityEngine.CoreModule", null,
            "https://docs.unity3d.com/2022.3/Documentation/ScriptReference/UnityEngine.CoreModule.html " +
            "(core engine, no package; not listed among the built-in packages of the 2022.3 Manual)");

        public static readonly Module PhysicsModule = new Module("UnityEngine.PhysicsModule", "com.unity.modules.physics",
            "https://docs.unity3d.com/2022.3/Documentation/Manual/com.unity.modules.physics.html " +
            "(\"The Physics module implements 3D physics in Unity\", Scripting API: UnityEngine.PhysicsModule; " +
            "Library/PackageCache/com.unity.modules.physics@1.0.0/package.json: version 1.0.0, type module)");

        public static readonly Module ImguiModule = new Module("UnityEngine.IMGUIModule", "com.unity.modules.imgui",
            "https://docs.unity3d.com/2022.3/Documentation/Manual/com.unity.modules.imgui.html " +
            "(Scripting API: UnityEngine.IMGUIModule, which lists GUI, GUILayout, GUILayoutOption, GUIContent, GUIStyle)");

        public static readonly Module AudioModule = new Module("UnityEngine.AudioModule", "com.unity.modules.audio",
            "https://docs.unity3d.com/2022.3/Documentation/Manual/com.unity.modules.audio.html " +
            "(Scripting API: UnityEngine.AudioModule; AudioListener: \"Implemented in: UnityEngine.AudioModule\")");

        public static readonly Module EditorCoreModule = new Module("UnityEditor.CoreModule", null,
            "https://docs.unity3d.com/2022.3/Documentation/ScriptReference/UnityEditor.CoreModule.html " +
            "(the editor itself, no package)");

        public static readonly Module[] Modules = { CoreModule, PhysicsModule, ImguiModule, AudioModule, EditorCoreModule };

        /// <summary>Full type name (namespace.Name, generic arity as `n, nested as Outer+Inner) → module.</summary>
        public static readonly IReadOnlyDictionary<string, Module> Types = Build();

        /// <summary>
        /// Class name of a serialized object (the "Name:" line after "--- !u!id &amp;fileID" in scenes, prefabs and
        /// other YAML assets the package ships) → module. The four scene settings objects and SceneRoots (the root
        /// order, class 1660057539, 2022.2+) are written into every scene by the editor and need no package.
        /// </summary>
        public static readonly IReadOnlyDictionary<string, Module> SerializedClasses = new Dictionary<string, Module>
        {
            ["GameObject"] = CoreModule, ["Transform"] = CoreModule, ["MonoBehaviour"] = CoreModule,
            ["MeshFilter"] = CoreModule, ["MeshRenderer"] = CoreModule, ["Camera"] = CoreModule, ["Light"] = CoreModule,
            ["Material"] = CoreModule, ["Mesh"] = CoreModule, ["Texture2D"] = CoreModule, ["PrefabInstance"] = CoreModule,
            ["OcclusionCullingSettings"] = CoreModule, ["RenderSettings"] = CoreModule,
            ["LightmapSettings"] = CoreModule, ["NavMeshSettings"] = CoreModule, ["SceneRoots"] = CoreModule,
            ["Rigidbody"] = PhysicsModule, ["BoxCollider"] = PhysicsModule, ["SphereCollider"] = PhysicsModule,
            ["CapsuleCollider"] = PhysicsModule, ["MeshCollider"] = PhysicsModule,
            ["CharacterController"] = PhysicsModule,
            ["AudioListener"] = AudioModule,
        };

        static Dictionary<string, Module> Build()
        {
            var t = new Dictionary<string, Module>();
            void Add(Module module, string ns, params string[] names)
            {
                foreach (var name in names) t.Add(ns + "." + name, module);
            }

            // UnityEngine.CoreModule: "Implemented in: UnityEngine.CoreModule" on each 2022.3 Scripting Reference page.
            Add(CoreModule, "UnityEngine",
                "AddComponentMenu", "Application", "Behaviour", "Bounds", "Camera", "Color", "Component", "Debug",
                "DefaultExecutionOrder", "DisallowMultipleComponent", "ExecuteAlways", "ExecuteInEditMode", "FilterMode", "GameObject", "Gizmos",
                "HeaderAttribute", "HelpURLAttribute", "HideFlags", "LayerMask", "LogType", "Material", "Mesh",
                "MeshFilter", "MeshRenderer", "MeshTopology", "MinAttribute", "MissingReferenceException",
                "MonoBehaviour", "Object", "PrimitiveType", "PropertyAttribute", "QualitySettings", "Quaternion",
                "RangeAttribute", "Rect", "Renderer", "RequireComponent", "ScriptableObject", "SerializeField", "Shader",
                "Texture", "Texture2D", "TextureFormat", "TextureWrapMode", "Time", "TooltipAttribute", "Transform",
                "UnityException", "Vector3", "WaitForFixedUpdate", "YieldInstruction");
            Add(CoreModule, "UnityEngine.Events",
                "ArgumentCache", "PersistentCall", "PersistentCallGroup", "PersistentListenerMode",
                "UnityAction", "UnityAction`1", "UnityAction`2", "UnityEvent", "UnityEvent`1", "UnityEvent`2",
                "UnityEventBase", "UnityEventCallState");
            Add(CoreModule, "UnityEngine.Rendering",
                "GraphicsSettings", "IndexFormat", "MeshUpdateFlags", "RenderPipeline", "RenderPipelineAsset",
                "ScriptableRenderContext", "SubMeshDescriptor", "VertexAttribute", "VertexAttributeDescriptor",
                "VertexAttributeFormat");

            // UnityEngine.PhysicsModule (com.unity.modules.physics): "Implemented in: UnityEngine.PhysicsModule"
            // (Rigidbody, Collider and its subclasses, Physics, ForceMode, QueryTriggerInteraction, SimulationMode,
            // RigidbodyInterpolation, RigidbodyConstraints, CharacterController).
            Add(PhysicsModule, "UnityEngine",
                "BoxCollider", "CapsuleCollider", "CharacterController", "Collider", "CollisionFlags", "ForceMode", "MeshCollider",
                "Physics", "QueryTriggerInteraction", "RaycastHit", "Rigidbody", "RigidbodyConstraints",
                "RigidbodyInterpolation", "SimulationMode", "SphereCollider");

            // UnityEngine.AudioModule (com.unity.modules.audio).
            Add(AudioModule, "UnityEngine", "AudioListener", "AudioSource");

            // UnityEngine.IMGUIModule (com.unity.modules.imgui).
            Add(ImguiModule, "UnityEngine", "GUI", "GUIContent", "GUILayout", "GUILayoutOption", "GUILayoutUtility", "GUIStyle");

            // UnityEditor.CoreModule: "Implemented in: UnityEditor.CoreModule".
            Add(EditorCoreModule, "UnityEditor",
                "AssetDatabase", "CanEditMultipleObjects", "CustomEditor", "DrawGizmo", "Editor", "EditorApplication",
                "EditorGUI", "EditorGUILayout", "GameObjectUtility", "GizmoType", "Handles", "MenuCommand", "MenuItem",
                "MessageType", "ObjectFactory", "PrefabUtility", "Selection", "SerializedObject", "SerializedProperty",
                "SerializedPropertyType", "Undo");
            // the drop hook (issue 13 item 1): also "Implemented in: UnityEditor.CoreModule"
            Add(EditorCoreModule, "UnityEditor",
                "ChangeGameObjectParentEventArgs", "CreateGameObjectHierarchyEventArgs", "EditorUtility",
                "InitializeOnLoadAttribute", "ObjectChangeEventStream", "ObjectChangeEvents",
                "ObjectChangeEvents+ObjectChangeEventsHandler", "ObjectChangeKind");
            Add(EditorCoreModule, "UnityEditor.SceneManagement", "PrefabStage", "PrefabStageUtility");
            // the shared multi-rope world (issue 18 item 4): "Implemented in: UnityEngine.CoreModule" (SystemInfo) and
            // "UnityEditor.CoreModule" (AssemblyReloadEvents, UCR Editor/Mono/AssemblyReloadEvents.cs)
            Add(CoreModule, "UnityEngine", "SystemInfo");
            Add(EditorCoreModule, "UnityEditor", "AssemblyReloadEvents", "AssemblyReloadEvents+AssemblyReloadCallback");
            return t;
        }
    }
}
