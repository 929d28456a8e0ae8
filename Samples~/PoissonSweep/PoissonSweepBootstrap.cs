using System;
using UnityEngine;

namespace HookeRope.Samples.PoissonSweep
{
    /// <summary>
    /// Poisson Sweep sample (Chen et al. 2022, Fig. 5): four ropes side by side with Poisson ratios 0, 0.3, 0.5
    /// and −0.8 are stretched and released by a grip moving up and down. ν = 0 keeps its radius, 0.3 and 0.5 thin
    /// (0.5 keeps the volume), −0.8 (auxetic) thickens. Built in code in Start; the grips move in FixedUpdate.
    /// </summary>
    public sealed class PoissonSweepBootstrap : MonoBehaviour
    {
        static readonly float[] s_PoissonRatios = { 0f, 0.3f, 0.5f, -0.8f };

        [SerializeField, Tooltip("Rest length of each rope (m).")]
        float m_RestLength = 1.5f;

        [SerializeField, Tooltip("Rest radius of each rope (m); thick so the radius change is easy to see.")]
        float m_Radius = 0.06f;

        [SerializeField, Tooltip("Largest strain of the sweep (dimensionless).")]
        float m_MaxStrain = 0.5f;

        [SerializeField, Tooltip("Period of one stretch-and-release cycle (s).")]
        float m_Period = 6f;

        Transform[] _grips = Array.Empty<Transform>();
        const float TopHeight = 3f;
        float _time;

        void OnValidate()
        {
            m_RestLength = Math.Max(0.1f, m_RestLength);
            m_Radius = Math.Max(0.001f, m_Radius);
            m_MaxStrain = Math.Min(Math.Max(0f, m_MaxStrain), 2f);
            m_Period = Math.Max(0.5f, m_Period);
        }

        void Start()
        {
            _grips = new Transform[s_PoissonRatios.Length];
            for (int i = 0; i < s_PoissonRatios.Length; i++)
            {
                float x = (i - 1.5f) * 0.6f;
                var top = new GameObject("Top ν=" + s_PoissonRatios[i]);
                top.transform.position = new Vector3(x, TopHeight, 0f);
                var grip = new GameObject("Grip ν=" + s_PoissonRatios[i]);
                grip.transform.position = new Vector3(x, TopHeight - m_RestLength, 0f);
                _grips[i] = grip.transform;

                var go = new GameObject("Rope ν=" + s_PoissonRatios[i], typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
                var rope = go.GetComponent<ElasticRope>();
                rope.RestLength = m_RestLength;
                rope.Radius = m_Radius;
                rope.PoissonRatio = s_PoissonRatios[i];
                rope.SegmentCount = 24;
                rope.PoissonThinning = true;
                rope.Necking = false;
                rope.Fracture = false;
                rope.StartAttachment.Point = top.transform;
                rope.EndAttachment.Point = grip.transform;
                rope.Rebuild();
                go.GetComponent<RopeMeshRenderer>().RadialSegments = 24;
            }
        }

        void FixedUpdate()
        {
            _time += Time.fixedDeltaTime;
            float strain = m_MaxStrain * 0.5f * (1f - MathF.Cos(2f * MathF.PI * _time / m_Period));
            for (int i = 0; i < _grips.Length; i++)
            {
                var p = _grips[i].position;
                _grips[i].position = new Vector3(p.x, TopHeight - m_RestLength * (1f + strain), p.z);
            }
        }
    }
}
