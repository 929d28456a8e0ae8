namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Component.</summary>
    public class Component : Object
    {
        /// <summary>The Transform attached to this GameObject.</summary>
        public Transform transform => throw Shim.NotRun;

        /// <summary>The game object this component is attached to.</summary>
        public GameObject gameObject => throw Shim.NotRun;

        /// <summary>Gets a reference to a component of type T on the same GameObject as the component specified.</summary>
        public T GetComponent<T>() => throw Shim.NotRun;

        /// <summary>Gets the component of the specified type, if it exists.</summary>
        public bool TryGetComponent<T>(out T component) => throw Shim.NotRun;
    }
}
