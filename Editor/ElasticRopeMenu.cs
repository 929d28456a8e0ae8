using UnityEditor;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>GameObject &gt; 3D Object &gt; Elastic Rope: a ready rope between two new anchor objects, with Undo.</summary>
    internal static class ElasticRopeMenu
    {
        /// <summary>Menu path of the create item.</summary>
        public const string MenuPath = "GameObject/3D Object/Elastic Rope";

        [MenuItem(MenuPath, false, 10)]
        static void CreateFromMenu(MenuCommand command) => Create(command.context as GameObject);

        /// <summary>
        /// Creates "Elastic Rope" (ElasticRope + RopeMeshRenderer) with two child anchors 1.6 m apart, so the
        /// default 2 m rope sags between them, registers the creation with Undo and places it as Unity places its own
        /// 3D objects (ObjectFactory.PlaceGameObject): as a child of <paramref name="parent"/> at its origin when given,
        /// else at the last active Scene view's pivot, inside the open prefab stage when there is one; the name is made
        /// unique among its siblings and the rope is selected. Returns the rope.
        /// </summary>
        public static ElasticRope Create(GameObject parent)
        {
            var root = new GameObject("Elastic Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
            var start = new GameObject("Rope Start");
            var end = new GameObject("Rope End");
            start.transform.SetParent(root.transform, worldPositionStays: false);
            end.transform.SetParent(root.transform, worldPositionStays: false);
            start.transform.localPosition = new Vector3(-0.8f, 0f, 0f);
            end.transform.localPosition = new Vector3(0.8f, 0f, 0f);

            var rope = root.GetComponent<ElasticRope>();
            rope.StartAttachment.Point = start.transform;
            rope.EndAttachment.Point = end.transform;

            Undo.RegisterCreatedObjectUndo(root, "Create Elastic Rope");
            ObjectFactory.PlaceGameObject(root, parent);
            return rope;
        }
    }
}
