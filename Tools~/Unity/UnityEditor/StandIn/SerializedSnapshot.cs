using System.Collections.Generic;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: a SerializedObject's copy of one target's serialized fields (deep copies, so edits stay
    /// in the copy until applied), as Unity's SerializedObject keeps its own serialized representation.
    /// </summary>
    internal sealed class SerializedSnapshot
    {
        internal SerializedSnapshot(object target)
        {
            Layout = SerializedLayout.Of(target.GetType());
            Values = new object[Layout.Members.Count];
            for (int i = 0; i < Values.Length; i++)
            {
                var member = Layout.Members[i];
                Values[i] = SerializedCopy.CopyValue(member.Field.GetValue(target), member.Type);
            }
        }

        internal SerializedLayout Layout { get; }

        internal object[] Values { get; }

        internal int IndexOf(SerializedMember member)
        {
            IReadOnlyList<SerializedMember> members = Layout.Members;
            for (int i = 0; i < members.Count; i++)
                if (ReferenceEquals(members[i], member)) return i;
            return -1;
        }
    }
}
