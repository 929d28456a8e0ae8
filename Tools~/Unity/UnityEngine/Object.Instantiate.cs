using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.Object: the Object.Instantiate overloads (cloning in <see cref="ObjectCloner"/>).</summary>
    public partial class Object
    {
        const string ObjectIsNullMessage = "The Object you want to instantiate is null.";
        const string CloneDestroyedMessage = "Instantiate failed because the clone was destroyed during creation. This can happen if DestroyImmediate is called in MonoBehaviour.Awake.";

        /// <summary>Clones the object original and returns the clone (same world position and rotation, no parent).</summary>
        public static Object Instantiate(Object original) =>
            Clone(original, null, worldSpace: true, hasPose: false, default, default, null);

        /// <summary>Clones the object original as a child of parent, keeping the original's local position and rotation.</summary>
        public static Object Instantiate(Object original, Transform parent) => Instantiate(original, parent, false);

        /// <summary>Clones the object original as a child of parent; instantiateInWorldSpace keeps the original's world position and rotation.</summary>
        public static Object Instantiate(Object original, Transform parent, bool instantiateInWorldSpace) =>
            parent == null ? Instantiate(original) : Clone(original, parent, instantiateInWorldSpace, hasPose: false, default, default, null);

        /// <summary>Clones the object original at position and rotation (world space).</summary>
        public static Object Instantiate(Object original, Vector3 position, Quaternion rotation) =>
            Clone(original, null, worldSpace: true, hasPose: true, position, rotation, null);

        /// <summary>Clones the object original as a child of parent at position and rotation (world space).</summary>
        public static Object Instantiate(Object original, Vector3 position, Quaternion rotation, Transform parent) =>
            parent == null ? Instantiate(original, position, rotation) : Clone(original, parent, worldSpace: true, hasPose: true, position, rotation, null);

        /// <summary>Clones the object original and returns the clone.</summary>
        public static T Instantiate<T>(T original) where T : Object => (T)Instantiate((Object)original);

        /// <summary>Clones the object original as a child of parent, keeping the original's local position and rotation.</summary>
        public static T Instantiate<T>(T original, Transform parent) where T : Object => Instantiate(original, parent, false);

        /// <summary>Clones the object original as a child of parent; worldPositionStays keeps the original's world position and rotation.</summary>
        public static T Instantiate<T>(T original, Transform parent, bool worldPositionStays) where T : Object =>
            (T)Instantiate((Object)original, parent, worldPositionStays);

        /// <summary>Clones the object original at position and rotation (world space).</summary>
        public static T Instantiate<T>(T original, Vector3 position, Quaternion rotation) where T : Object =>
            (T)Instantiate((Object)original, position, rotation);

        /// <summary>Clones the object original as a child of parent at position and rotation (world space).</summary>
        public static T Instantiate<T>(T original, Vector3 position, Quaternion rotation, Transform parent) where T : Object =>
            (T)Instantiate((Object)original, position, rotation, parent);

        // ---- stand-in internals -----------------------------------------------------------------------------
        /// <summary>
        /// Clones <paramref name="original"/> into the scene. Without a pose: no parent → the original's world position
        /// and rotation; a parent → its local position and rotation (or world ones with <paramref name="worldSpace"/>).
        /// With a pose: that world position and rotation. Local scale is the original's. The root is named
        /// <paramref name="rootName"/>, or the original's name + "(Clone)".
        /// </summary>
        internal static Object Clone(Object original, Transform parent, bool worldSpace, bool hasPose, Vector3 position, Quaternion rotation, string rootName)
        {
            if (original is null) throw new ArgumentException(ObjectIsNullMessage);
            original.EnsureAlive();
            if (original is ScriptableObject scriptable) return CloneScriptable(scriptable, parent, hasPose);
            if (original is Material material)
            {
                if (hasPose || parent != null) throw StandInError.Unsupported("Object.Instantiate of a Material with a parent or pose");
                return new Material(material) { name = material.NameCore + "(Clone)" };
            }
            if (!(original is GameObject) && !(original is Component))
                throw StandInError.Unsupported("Object.Instantiate of a " + original.GetType().FullName);

            var sourceRoot = original as GameObject ?? ((Component)original).gameObject;
            var source = sourceRoot.transform;
            var (root, result) = ObjectCloner.CloneDetached(original);
            var t = root.transform;
            if (hasPose)
            {
                if (parent != null) t.SetParent(parent, false);
                t.SetPositionAndRotation(position, rotation);
            }
            else if (parent == null) t.SetPositionAndRotation(source.position, source.rotation);
            else
            {
                t.localPosition = source.localPosition;
                t.localRotation = source.localRotation;
                t.SetParent(parent, false);
                if (worldSpace) t.SetPositionAndRotation(source.position, source.rotation);
            }
            root.name = rootName ?? sourceRoot.NameCore + "(Clone)";
            SceneHooks.Attach(root);
            if (result == null) throw new UnityException(CloneDestroyedMessage);
            return result;
        }

        static Object CloneScriptable(ScriptableObject original, Transform parent, bool hasPose)
        {
            if (hasPose) throw new ArgumentException("Cannot instantiate a ScriptableObject with a position and rotation");
            if (parent != null) throw StandInError.Unsupported("Object.Instantiate of a ScriptableObject with a parent");
            var clone = ScriptableObject.Construct(original.GetType());
            SerializedCopy.CopyFields(original, clone, o => o);
            clone.name = original.NameCore + "(Clone)";
            clone.hideFlags = original.hideFlags;
            clone.SendCreateMessages();
            if (clone == null) throw new UnityException(CloneDestroyedMessage);
            return clone;
        }
    }
}
