using System.Collections;

namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Transform.</summary>
    public class Transform : Component, IEnumerable
    {
        /// <summary>The world space position of the Transform.</summary>
        public Vector3 position { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <inheritdoc/>
        public IEnumerator GetEnumerator() => throw Shim.NotRun;
    }
}
