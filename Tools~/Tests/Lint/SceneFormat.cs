using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text.RegularExpressions;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// The shape of a scene file as Unity 2022.3 saves it, checked on the text: the YAML header, the four scene
    /// settings objects with fixed file IDs and their 2022.3 serialized versions, the SceneRoots object (class 1660057539,
    /// written since 2022.2) listing exactly the root Transforms, Transforms without m_RootOrder, m_ObjectHideFlags on
    /// every object, and the 2022.3 Camera key list (physical-camera keys). Reference: scenes saved by 2022.3 in Unity's
    /// own packages (com.unity.cinemachine 3.1.3 samples, "unity": "2022.3").
    /// </summary>
    public static class SceneFormat
    {
        /// <summary>File ID Unity gives the SceneRoots object.</summary>
        public const long SceneRootsFileId = 9223372036854775807;

        /// <summary>Class ID of SceneRoots.</summary>
        public const int SceneRootsClass = 1660057539;

        /// <summary>The settings objects every 2022.3 scene opens with: class ID, file ID, type, serializedVersion.</summary>
        public static readonly (int ClassId, long FileId, string Type, int Version)[] Settings =
        {
            (29, 1, "OcclusionCullingSettings", 2),
            (104, 2, "RenderSettings", 9),
            (157, 3, "LightmapSettings", 12),
            (196, 4, "NavMeshSettings", 2),
        };

        /// <summary>The keys of a Camera as 2022.3 writes them, in order.</summary>
        public static readonly string[] CameraKeys =
        {
            "m_ObjectHideFlags", "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset", "m_GameObject", "m_Enabled",
            "serializedVersion", "m_ClearFlags", "m_BackGroundColor", "m_projectionMatrixMode", "m_GateFitMode", "m_FOVAxisMode",
            "m_Iso", "m_ShutterSpeed", "m_Aperture", "m_FocusDistance", "m_FocalLength", "m_BladeCount", "m_Curvature",
            "m_BarrelClipping", "m_Anamorphism", "m_SensorSize", "m_LensShift", "m_NormalizedViewPortRect", "near clip plane",
            "far clip plane", "field of view", "orthographic", "orthographic size", "m_Depth", "m_CullingMask", "m_RenderingPath",
            "m_TargetTexture", "m_TargetDisplay", "m_TargetEye", "m_HDR", "m_AllowMSAA", "m_AllowDynamicResolution", "m_ForceIntoRT",
            "m_OcclusionCulling", "m_StereoConvergence", "m_StereoSeparation",
        };

        static readonly Regex DocumentHeader = new Regex(@"^--- !u!(\d+) &(-?\d+)( stripped)?$", RegexOptions.Multiline);
        static readonly Regex Reference = new Regex(@"\{fileID: (-?\d+)\}");

        /// <summary>One object of a scene: class ID, file ID, type name and its text (the lines after the type name).</summary>
        public sealed class Document
        {
            internal Document(int classId, long fileId, string type, string body)
            {
                ClassId = classId;
                FileId = fileId;
                Type = type;
                Body = body;
            }

            /// <summary>Unity class ID.</summary>
            public int ClassId { get; }
            /// <summary>Local file ID.</summary>
            public long FileId { get; }
            /// <summary>Type name (the document's single top-level key).</summary>
            public string Type { get; }
            /// <summary>The mapping's lines, each indented by two spaces.</summary>
            public string Body { get; }

            /// <summary>Top-level keys in order.</summary>
            public IEnumerable<string> Keys => Body.Split('\n').Where(l => l.StartsWith("  ", StringComparison.Ordinal) && l.Length > 2 && l[2] != ' ' && l[2] != '-')
                .Select(l => l.Substring(2, l.IndexOf(':') - 2));

            /// <summary>The scalar value of top-level key <paramref name="key"/>, or null.</summary>
            public string Value(string key)
            {
                var m = Regex.Match(Body, "^  " + Regex.Escape(key) + ": ?(.*)$", RegexOptions.Multiline);
                return m.Success ? m.Groups[1].Value.TrimEnd('\r') : null;
            }
        }

        /// <summary>Splits scene text into its objects (throws on a document without a type line).</summary>
        public static List<Document> Parse(string text)
        {
            var docs = new List<Document>();
            var matches = DocumentHeader.Matches(text);
            for (int i = 0; i < matches.Count; i++)
            {
                int start = matches[i].Index + matches[i].Length + 1;
                int end = i + 1 < matches.Count ? matches[i + 1].Index : text.Length;
                string chunk = start <= end ? text.Substring(start, end - start) : "";
                int newline = chunk.IndexOf('\n');
                string typeLine = newline < 0 ? chunk : chunk.Substring(0, newline);
                if (!typeLine.EndsWith(":", StringComparison.Ordinal)) throw new FormatException("object &" + matches[i].Groups[2].Value + " has no type line");
                docs.Add(new Document(int.Parse(matches[i].Groups[1].Value, CultureInfo.InvariantCulture),
                    long.Parse(matches[i].Groups[2].Value, CultureInfo.InvariantCulture), typeLine.TrimEnd(':'),
                    newline < 0 ? "" : chunk.Substring(newline + 1)));
            }
            return docs;
        }

        /// <summary>The problems of scene <paramref name="name"/> with text <paramref name="text"/>, empty when it is in the 2022.3 format.</summary>
        public static List<string> Problems(string name, string text)
        {
            var problems = new List<string>();
            void Problem(string message) => problems.Add(name + ": " + message);

            if (!text.StartsWith("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n", StringComparison.Ordinal)) Problem("does not start with Unity's YAML header");
            List<Document> docs;
            try { docs = Parse(text); }
            catch (FormatException e) { Problem(e.Message); return problems; }

            for (int i = 0; i < Settings.Length; i++)
            {
                var want = Settings[i];
                if (docs.Count <= i || docs[i].ClassId != want.ClassId || docs[i].FileId != want.FileId || docs[i].Type != want.Type)
                {
                    Problem("object " + (i + 1) + " must be !u!" + want.ClassId + " &" + want.FileId + " " + want.Type);
                    continue;
                }
                if (docs[i].Value("serializedVersion") != want.Version.ToString(CultureInfo.InvariantCulture))
                    Problem(want.Type + " serializedVersion " + docs[i].Value("serializedVersion") + ", 2022.3 writes " + want.Version);
            }
            var lightmap = docs.FirstOrDefault(d => d.ClassId == 157);
            if (lightmap != null && !Regex.IsMatch(lightmap.Body, @"m_LightmapEditorSettings:\n    serializedVersion: 12\n"))
                Problem("LightmapSettings.m_LightmapEditorSettings must be serializedVersion 12");
            var navMesh = docs.FirstOrDefault(d => d.ClassId == 196);
            if (navMesh != null)
            {
                if (!Regex.IsMatch(navMesh.Body, @"m_BuildSettings:\n    serializedVersion: 3\n")) Problem("NavMeshSettings.m_BuildSettings must be serializedVersion 3 (2022.2+)");
                if (!navMesh.Body.Contains("    buildHeightMesh: ")) Problem("NavMeshSettings.m_BuildSettings lacks buildHeightMesh");
                if (navMesh.Body.Contains("accuratePlacement")) Problem("NavMeshSettings.m_BuildSettings has accuratePlacement, which 2022.3 no longer writes");
            }

            foreach (var doc in docs)
            {
                if (doc.Value("m_ObjectHideFlags") == null) Problem(doc.Type + " &" + doc.FileId + " lacks m_ObjectHideFlags");
                switch (doc.ClassId)
                {
                    case 1:
                        if (doc.Value("serializedVersion") != "6") Problem("GameObject &" + doc.FileId + " must be serializedVersion 6");
                        break;
                    case 4:
                        if (doc.Value("serializedVersion") != "2") Problem("Transform &" + doc.FileId + " must be serializedVersion 2");
                        if (doc.Value("m_RootOrder") != null) Problem("Transform &" + doc.FileId + " has m_RootOrder (pre-2022.2; SceneRoots orders the roots)");
                        break;
                    case 20:
                        if (!doc.Keys.SequenceEqual(CameraKeys)) Problem("Camera &" + doc.FileId + " keys differ from 2022.3's: " + string.Join(", ", doc.Keys));
                        break;
                    case 108:
                        if (doc.Value("serializedVersion") != "10") Problem("Light &" + doc.FileId + " must be serializedVersion 10");
                        break;
                }
            }

            var roots = docs.Where(d => d.ClassId == 4 && d.Value("m_Father") == "{fileID: 0}").Select(d => d.FileId).ToList();
            var sceneRoots = docs.Where(d => d.ClassId == SceneRootsClass).ToList();
            if (sceneRoots.Count != 1) { Problem("has " + sceneRoots.Count + " SceneRoots objects, 2022.3 writes one"); return problems; }
            var last = docs[docs.Count - 1];
            if (last != sceneRoots[0]) Problem("SceneRoots must be the last object");
            if (sceneRoots[0].FileId != SceneRootsFileId || sceneRoots[0].Type != "SceneRoots") Problem("SceneRoots must be !u!1660057539 &" + SceneRootsFileId);
            int listStart = sceneRoots[0].Body.IndexOf("  m_Roots:", StringComparison.Ordinal);
            var listed = listStart < 0 ? new List<long>() : Reference.Matches(sceneRoots[0].Body.Substring(listStart)).Cast<Match>()
                .Select(m => long.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture)).ToList();
            if (listed.Count != listed.Distinct().Count()) Problem("SceneRoots lists a Transform twice");
            foreach (var id in roots.Except(listed)) Problem("root Transform &" + id + " is missing from SceneRoots");
            foreach (var id in listed.Except(roots)) Problem("SceneRoots lists &" + id + ", which is not a root Transform");
            return problems;
        }
    }
}
