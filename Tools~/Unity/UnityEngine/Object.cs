// API shim: signatures copied from the Unity 2022.3 Scripting Reference. Bodies are never run.
namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Object.</summary>
    public class Object
    {
        /// <summary>The name of the object.</summary>
        public string name { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Should the object be hidden, saved with the Scene or modifiable by the user?</summary>
        public HideFlags hideFlags { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Removes a GameObject, component or asset.</summary>
        public static void Destroy(Object obj, float t = 0.0F) => throw Shim.NotRun;

        /// <summary>Destroys the object obj immediately. You are strongly recommended to use Destroy instead.</summary>
        public static void DestroyImmediate(Object obj, bool allowDestroyingAssets = false) => throw Shim.NotRun;

        /// <summary>Does the object exist?</summary>
        public static implicit operator bool(Object exists) => throw Shim.NotRun;

        /// <summary>Compares if two objects refer to the same.</summary>
        public static bool operator ==(Object x, Object y) => throw Shim.NotRun;

        /// <summary>Compares if two objects refer to a different object.</summary>
        public static bool operator !=(Object x, Object y) => throw Shim.NotRun;

        /// <inheritdoc/>
        public override bool Equals(object other) => throw Shim.NotRun;

        /// <inheritdoc/>
        public override int GetHashCode() => throw Shim.NotRun;
    }
}
