using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: what a Mesh's renderers have been told. Every data change is recorded with its flags;
    /// a change without MeshUpdateFlags.DontNotifyMeshUsers (or Mesh.MarkModified) notifies the users, which then
    /// see the Mesh's current bounds. A silent change leaves <see cref="UsersUpToDate"/> false until the next
    /// notification — the stale-culling situation the MeshUpdateFlags.DontNotifyMeshUsers documentation warns about.
    /// The log keeps the newest 1024 records and does not allocate once it has grown.
    /// </summary>
    internal sealed class MeshUpdateLog
    {
        const int Capacity = 1024;
        readonly List<MeshUpdateRecord> _records = new List<MeshUpdateRecord>(Capacity);

        /// <summary>Recorded changes, oldest first (the newest 1024 at most).</summary>
        internal IReadOnlyList<MeshUpdateRecord> Records => _records;

        /// <summary>How many changes notified the users.</summary>
        internal int NotificationCount { get; private set; }

        /// <summary>False after a silent change, until the users are notified again.</summary>
        internal bool UsersUpToDate { get; private set; } = true;

        /// <summary>The Mesh bounds as of the last notification (what a renderer culls with).</summary>
        internal Bounds BoundsSeenByUsers { get; private set; }

        /// <summary>The newest record (default before any change).</summary>
        internal MeshUpdateRecord Last => _records.Count > 0 ? _records[_records.Count - 1] : default;

        /// <summary>Records <paramref name="call"/>; notifies unless the flags carry DontNotifyMeshUsers.</summary>
        internal void Record(string call, MeshUpdateFlags flags, Bounds currentBounds)
        {
            bool notify = (flags & MeshUpdateFlags.DontNotifyMeshUsers) == 0;
            if (_records.Count == Capacity) _records.RemoveRange(0, Capacity / 2);
            _records.Add(new MeshUpdateRecord(call, flags, notify));
            if (notify)
            {
                NotificationCount++;
                UsersUpToDate = true;
                BoundsSeenByUsers = currentBounds;
            }
            else
            {
                UsersUpToDate = false;
            }
        }

        /// <summary>The newest record of <paramref name="call"/>, or default.</summary>
        internal MeshUpdateRecord LastOf(string call)
        {
            for (int i = _records.Count - 1; i >= 0; i--)
                if (_records[i].Call == call) return _records[i];
            return default;
        }
    }
}
