using System;
using UnityEngine;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the serialized state of Unity's built-in components that Object.Instantiate copies onto a
    /// clone, through their public properties: MeshFilter (mesh), Renderer (enabled, materials), Rigidbody (mass,
    /// drag, angular drag, gravity, kinematic, interpolation), colliders (enabled, trigger, shape). Velocities are
    /// run-time state, not serialized, so clones start at rest as in Unity. Transforms are placed by the cloner.
    /// Any other built-in component type throws: its state would otherwise be silently lost.
    /// </summary>
    internal static class BuiltinComponentState
    {
        /// <summary>Copies the serialized state of built-in <paramref name="source"/> onto <paramref name="target"/> (same type).</summary>
        internal static void Copy(Component source, Component target, Func<Object, Object> remap)
        {
            switch (source)
            {
                case Transform _:
                    return;
                case MeshFilter filter:
                    ((MeshFilter)target).sharedMesh = (Mesh)remap(filter.sharedMesh);
                    return;
                case MeshRenderer renderer:
                {
                    var copy = (MeshRenderer)target;
                    var materials = renderer.sharedMaterials;
                    var mapped = new Material[materials.Length];
                    for (int i = 0; i < materials.Length; i++) mapped[i] = (Material)remap(materials[i]);
                    copy.sharedMaterials = mapped;
                    copy.enabled = renderer.enabled;
                    return;
                }
                case Rigidbody body:
                {
                    var copy = (Rigidbody)target;
                    copy.mass = body.mass;
                    copy.drag = body.drag;
                    copy.angularDrag = body.angularDrag;
                    copy.useGravity = body.useGravity;
                    copy.isKinematic = body.isKinematic;
                    copy.interpolation = body.interpolation;
                    return;
                }
                case SphereCollider sphere:
                {
                    var copy = (SphereCollider)target;
                    copy.center = sphere.center;
                    copy.radius = sphere.radius;
                    CopyCollider(sphere, copy);
                    return;
                }
                case BoxCollider box:
                {
                    var copy = (BoxCollider)target;
                    copy.center = box.center;
                    copy.size = box.size;
                    CopyCollider(box, copy);
                    return;
                }
                case CapsuleCollider capsule:
                {
                    var copy = (CapsuleCollider)target;
                    copy.center = capsule.center;
                    copy.radius = capsule.radius;
                    copy.height = capsule.height;
                    copy.direction = capsule.direction;
                    CopyCollider(capsule, copy);
                    return;
                }
                default:
                    throw StandInError.Unsupported("Object.Instantiate of a GameObject with a " + source.GetType().FullName + " component");
            }
        }

        static void CopyCollider(Collider source, Collider target)
        {
            target.isTrigger = source.isTrigger;
            target.enabled = source.enabled;
        }
    }
}
