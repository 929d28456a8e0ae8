using System;
using System.Collections.Generic;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.ObjectChangeEventStream: the events published by ObjectChangeEvents.changesPublished. The
    /// stand-in records CreateGameObjectHierarchy and ChangeGameObjectParent only, so only their getters exist.
    /// </summary>
    public struct ObjectChangeEventStream : IDisposable
    {
        internal readonly struct Event
        {
            internal Event(ObjectChangeKind kind, CreateGameObjectHierarchyEventArgs created, ChangeGameObjectParentEventArgs parent)
            {
                Kind = kind;
                Created = created;
                Parent = parent;
            }

            internal ObjectChangeKind Kind { get; }
            internal CreateGameObjectHierarchyEventArgs Created { get; }
            internal ChangeGameObjectParentEventArgs Parent { get; }
        }

        Event[] m_Events;

        internal ObjectChangeEventStream(List<Event> events) { m_Events = events.ToArray(); }

        /// <summary>Number of events in the stream.</summary>
        public int length => m_Events?.Length ?? 0;

        /// <summary>True while the stream holds its events (false after Dispose or for a default stream).</summary>
        public bool isCreated => m_Events != null;

        /// <summary>The kind of the event at <paramref name="eventIdx"/>.</summary>
        public ObjectChangeKind GetEventType(int eventIdx) => At(eventIdx).Kind;

        /// <summary>The data of the CreateGameObjectHierarchy event at <paramref name="eventIdx"/> (InvalidOperationException for another kind).</summary>
        public void GetCreateGameObjectHierarchyEvent(int eventIdx, out CreateGameObjectHierarchyEventArgs data) =>
            data = Checked(eventIdx, ObjectChangeKind.CreateGameObjectHierarchy).Created;

        /// <summary>The data of the ChangeGameObjectParent event at <paramref name="eventIdx"/> (InvalidOperationException for another kind).</summary>
        public void GetChangeGameObjectParentEvent(int eventIdx, out ChangeGameObjectParentEventArgs data) =>
            data = Checked(eventIdx, ObjectChangeKind.ChangeGameObjectParent).Parent;

        /// <summary>Releases the events (Unity: do not dispose the stream passed to a changesPublished callback).</summary>
        public void Dispose() => m_Events = null;

        Event At(int eventIdx)
        {
            if (m_Events == null) throw new ObjectDisposedException(nameof(ObjectChangeEventStream));
            if (eventIdx < 0 || eventIdx >= m_Events.Length) throw new IndexOutOfRangeException("Index " + eventIdx + " is out of range of '" + m_Events.Length + "' Length.");
            return m_Events[eventIdx];
        }

        Event Checked(int eventIdx, ObjectChangeKind expected)
        {
            var evt = At(eventIdx);
            if (evt.Kind != expected) throw new InvalidOperationException($"Asked for event kind {expected}, but found {evt.Kind} instead.");
            return evt;
        }
    }
}
