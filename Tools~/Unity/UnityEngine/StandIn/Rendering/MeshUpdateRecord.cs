using UnityEngine.Rendering;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: one recorded change of a Mesh (which call, its MeshUpdateFlags, and whether the Mesh's users
    /// — its renderers — were notified, i.e. the call did not pass MeshUpdateFlags.DontNotifyMeshUsers).
    /// </summary>
    internal readonly struct MeshUpdateRecord
    {
        /// <summary>Records a call.</summary>
        internal MeshUpdateRecord(string call, MeshUpdateFlags flags, bool notifiedUsers)
        {
            Call = call;
            Flags = flags;
            NotifiedUsers = notifiedUsers;
        }

        /// <summary>The Mesh member called, e.g. "SetVertexBufferData".</summary>
        internal string Call { get; }

        /// <summary>The flags passed (Default for calls without flags).</summary>
        internal MeshUpdateFlags Flags { get; }

        /// <summary>True when renderers using the Mesh were told about the change.</summary>
        internal bool NotifiedUsers { get; }

        /// <summary>"Call(Flags) notified|silent".</summary>
        public override string ToString() => Call + "(" + Flags + ") " + (NotifiedUsers ? "notified" : "silent");
    }
}
