namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: one object of a Unity YAML file ("--- !u!&lt;classID&gt; &amp;&lt;fileID&gt;" then
    /// "&lt;TypeName&gt;:" and its fields). ClassID reference: Unity Manual "YAML class ID reference".
    /// </summary>
    internal sealed class UnityYamlDocument
    {
        internal UnityYamlDocument(int classId, long fileId, bool stripped, string typeName, YamlMapping body, int line)
        {
            ClassId = classId;
            FileId = fileId;
            Stripped = stripped;
            TypeName = typeName;
            Body = body;
            Line = line;
        }

        /// <summary>Unity's class ID (1 GameObject, 4 Transform, 23 MeshRenderer, 33 MeshFilter, 114 MonoBehaviour …).</summary>
        internal int ClassId { get; }

        /// <summary>The object's local file ID, the target of {fileID: …} references in the same file.</summary>
        internal long FileId { get; }

        /// <summary>True for a "stripped" stub of an object that lives in a nested prefab.</summary>
        internal bool Stripped { get; }

        /// <summary>The type name line ("GameObject", "MonoBehaviour" …).</summary>
        internal string TypeName { get; }

        /// <summary>The object's fields.</summary>
        internal YamlMapping Body { get; }

        /// <summary>1-based line of the "---" header.</summary>
        internal int Line { get; }
    }
}
