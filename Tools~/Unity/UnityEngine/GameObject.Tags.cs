using HookeRope.StandIn;

namespace UnityEngine
{
    public sealed partial class GameObject
    {
        /// <summary>
        /// Not part of Unity: the tags every Unity project defines (Manual, "Tags"; the Tag Manager lists them as
        /// built in). A project's own tags live in its TagManager asset, which the stand-in does not model.
        /// </summary>
        internal static readonly string[] BuiltInTags = { "Untagged", "Respawn", "Finish", "EditorOnly", "MainCamera", "Player", "GameController" };

        string m_Tag = "Untagged";

        /// <summary>The tag of this game object.</summary>
        public string tag
        {
            get { EnsureAlive(); return m_Tag; }
            set
            {
                EnsureAlive();
                m_Tag = BuiltIn(value);
            }
        }

        /// <summary>Is this game object tagged with tag?</summary>
        public bool CompareTag(string tag)
        {
            EnsureAlive();
            return string.Equals(m_Tag, BuiltIn(tag), System.StringComparison.Ordinal);
        }

        /// <summary>The tag itself when it is one of <see cref="BuiltInTags"/>; else the stand-in refuses it (a project tag is not modelled).</summary>
        internal static string BuiltIn(string tag)
        {
            for (int i = 0; i < BuiltInTags.Length; i++)
                if (string.Equals(BuiltInTags[i], tag, System.StringComparison.Ordinal)) return BuiltInTags[i];
            throw StandInError.Unsupported("the tag '" + tag + "' (only Unity's built-in tags are modelled: the project's TagManager is not)");
        }
    }
}
