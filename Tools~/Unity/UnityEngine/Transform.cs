using System.Collections;

namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Transform.</summary>
    public class Transform : Component, IEnumerable
    {
        /// <summary>The world space position of the Transform.</summary>
        public Vector3 position { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>A Quaternion that stores the rotation of the Transform in world space.</summary>
        public Quaternion rotation { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Position of the transform relative to the parent transform.</summary>
        public Vector3 localPosition { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The rotation of the transform relative to the transform rotation of the parent.</summary>
        public Quaternion localRotation { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The scale of the transform relative to the GameObjects parent.</summary>
        public Vector3 localScale { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The global scale of the object (Read Only).</summary>
        public Vector3 lossyScale => throw Shim.NotRun;

        /// <summary>The parent of the transform.</summary>
        public Transform parent { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Set the parent of the transform.</summary>
        public void SetParent(Transform parent, bool worldPositionStays) => throw Shim.NotRun;

        /// <summary>Transforms position from local space to world space.</summary>
        public Vector3 TransformPoint(Vector3 position) => throw Shim.NotRun;

        /// <summary>Transforms position from world space to local space.</summary>
        public Vector3 InverseTransformPoint(Vector3 position) => throw Shim.NotRun;

        /// <summary>Transforms vector from world space to local space. This operation is affected by scale.</summary>
        public Vector3 InverseTransformVector(Vector3 vector) => throw Shim.NotRun;

        /// <summary>Transforms a direction from world space to local space. This operation is unaffected by scale.</summary>
        public Vector3 InverseTransformDirection(Vector3 direction) => throw Shim.NotRun;

        /// <inheritdoc/>
        public IEnumerator GetEnumerator() => throw Shim.NotRun;
    }
}
