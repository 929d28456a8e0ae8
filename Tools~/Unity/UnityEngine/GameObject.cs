using System;

namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.GameObject.</summary>
    public sealed class GameObject : Object
    {
        /// <summary>Creates a new game object, named name.</summary>
        public GameObject(string name) => throw Shim.NotRun;

        /// <summary>Creates a game object and attaches the specified components.</summary>
        public GameObject(string name, params Type[] components) => throw Shim.NotRun;

        /// <summary>The Transform attached to this GameObject.</summary>
        public Transform transform => throw Shim.NotRun;

        /// <summary>The layer the GameObject is in.</summary>
        public int layer { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Adds a component class of type componentType to the GameObject.</summary>
        public T AddComponent<T>() where T : Component => throw Shim.NotRun;

        /// <summary>Returns the component of Type type if the game object has one attached, null if it doesn't.</summary>
        public T GetComponent<T>() => throw Shim.NotRun;

        /// <summary>Creates a game object with a primitive mesh renderer and appropriate collider.</summary>
        public static GameObject CreatePrimitive(PrimitiveType type) => throw Shim.NotRun;
    }
}
