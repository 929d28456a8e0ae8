using System;
using UnityEngine;

namespace HookeRope.Samples.CollisionBend
{
    /// <summary>
    /// Collision Bend sample (Chen et al. 2022, Fig. 9a): one rope is pulled down over a horizontal cylinder
    /// (its CapsuleCollider) and another over a box, so each bends around the shape and stretches. The grips
    /// start above the shapes and are lowered in the first seconds, so the ropes settle on top of them.
    /// Built in code in Start.
    /// </summary>
    [DefaultExecutionOrder(-200)] // moves the grips before the ropes (ElasticRope: -100) step on them
    public sealed class CollisionBendBootstrap : MonoBehaviour
    {
        [SerializeField, Tooltip("Rest length of each rope (m).")]
        float m_RestLength = 2.6f;

        [SerializeField, Tooltip("Rest radius of each rope (m).")]
        float m_Radius = 0.02f;

        [SerializeField, Tooltip("Height the grips are lowered to (m); the cylinder top is at 1.25 m.")]
        float m_GripHeight = 0.3f;

        [SerializeField, Tooltip("Time to lower the grips (s).")]
        float m_LowerTime = 3f;

        [SerializeField, Tooltip("Coulomb friction between rope and shapes (dimensionless).")]
        float m_Friction = 0.2f;

        Transform[] _grips = Array.Empty<Transform>();
        const float StartHeight = 2f;
        float _time;

        void OnValidate()
        {
            m_RestLength = Math.Max(0.1f, m_RestLength);
            m_Radius = Math.Max(0.001f, m_Radius);
            m_LowerTime = Math.Max(0.1f, m_LowerTime);
            m_Friction = Math.Min(Math.Max(0f, m_Friction), 2f);
        }

        void Start()
        {
            var cylinder = GameObject.CreatePrimitive(PrimitiveType.Cylinder);
            cylinder.name = "Cylinder";
            cylinder.transform.position = new Vector3(0f, 1f, 0f);
            cylinder.transform.rotation = Quaternion.Euler(90f, 0f, 0f);
            cylinder.transform.localScale = new Vector3(0.5f, 0.6f, 0.5f);

            var box = GameObject.CreatePrimitive(PrimitiveType.Cube);
            box.name = "Box";
            box.transform.position = new Vector3(0f, 1f, 2f);
            box.transform.localScale = new Vector3(0.5f, 0.5f, 0.8f);

            _grips = new Transform[4];
            BuildRope("Rope over cylinder", 0f, cylinder.GetComponent<Collider>(), 0);
            BuildRope("Rope over box", 2f, box.GetComponent<Collider>(), 2);
        }

        void BuildRope(string name, float z, Collider shape, int gripIndex)
        {
            var left = new GameObject(name + " left grip");
            left.transform.position = new Vector3(-1.2f, StartHeight, z);
            var right = new GameObject(name + " right grip");
            right.transform.position = new Vector3(1.2f, StartHeight, z);
            _grips[gripIndex] = left.transform;
            _grips[gripIndex + 1] = right.transform;

            var go = new GameObject(name, typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
            var rope = go.GetComponent<ElasticRope>();
            rope.RestLength = m_RestLength;
            rope.Radius = m_Radius;
            rope.SegmentCount = 60;
            rope.Substeps = 8;
            rope.Fracture = false;
            rope.CollisionMode = RopeCollisionMode.ListedColliders;
            rope.Colliders = new[] { shape };
            rope.Friction = m_Friction;
            rope.StartAttachment.Point = left.transform;
            rope.EndAttachment.Point = right.transform;
            rope.Rebuild();
        }

        void FixedUpdate()
        {
            _time += Time.fixedDeltaTime;
            float t = Math.Min(1f, _time / m_LowerTime);
            float height = StartHeight + (m_GripHeight - StartHeight) * t;
            for (int i = 0; i < _grips.Length; i++)
            {
                if (_grips[i] == null) continue;
                var p = _grips[i].position;
                _grips[i].position = new Vector3(p.x, height, p.z);
            }
        }
    }
}
