using System;
using System.Globalization;
using UnityEngine;

namespace HookeRope.Samples.NeckingAndFracture
{
    /// <summary>
    /// Necking and Fracture sample (Chen et al. 2022, Figs. 6–8): three ropes with neck onset radii r_min = 0.8,
    /// 0.75 and 0.7 of R, meshed with 8, 16 and 32 radial segments, are pulled at constant speed through the full
    /// sequence: Poisson thinning, a neck at the defect, and the break with burred ends. Each break is logged
    /// with its position and the peak tension. Built in code in Start.
    /// </summary>
    public sealed class NeckingAndFractureBootstrap : MonoBehaviour
    {
        static readonly float[] s_NeckFractions = { 0.8f, 0.75f, 0.7f };
        static readonly int[] s_RadialSegments = { 8, 16, 32 };

        [SerializeField, Tooltip("Rest length of each rope (m).")]
        float m_RestLength = 1.2f;

        [SerializeField, Tooltip("Rest radius of each rope (m).")]
        float m_Radius = 0.05f;

        [SerializeField, Tooltip("Pull speed of the grips (m/s).")]
        float m_PullSpeed = 0.12f;

        [SerializeField, Tooltip("Strain at which the ropes break (dimensionless).")]
        float m_BreakStrain = 1.5f;

        Transform[] _grips = Array.Empty<Transform>();

        void OnValidate()
        {
            m_RestLength = Math.Max(0.1f, m_RestLength);
            m_Radius = Math.Max(0.001f, m_Radius);
            m_PullSpeed = Math.Max(0.001f, m_PullSpeed);
            m_BreakStrain = Math.Max(0.01f, m_BreakStrain);
        }

        void Start()
        {
            _grips = new Transform[s_NeckFractions.Length];
            for (int i = 0; i < s_NeckFractions.Length; i++)
            {
                float x = (i - 1f) * 0.8f;
                var top = new GameObject("Top r_min=" + s_NeckFractions[i] + "R");
                top.transform.position = new Vector3(x, 3f, 0f);
                var grip = new GameObject("Grip r_min=" + s_NeckFractions[i] + "R");
                grip.transform.position = new Vector3(x, 3f - m_RestLength, 0f);
                _grips[i] = grip.transform;

                var go = new GameObject("Rope r_min=" + s_NeckFractions[i] + "R", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
                var rope = go.GetComponent<ElasticRope>();
                rope.RestLength = m_RestLength;
                rope.Radius = m_Radius;
                rope.PoissonRatio = 0.5f;
                rope.SegmentCount = 40;
                rope.PoissonThinning = true;
                rope.Necking = true;
                rope.NeckRadiusFraction = s_NeckFractions[i];
                rope.DefectPosition = 0.5f;
                rope.Fracture = true;
                rope.BreakStrain = m_BreakStrain;
                rope.StartAttachment.Point = top.transform;
                rope.EndAttachment.Point = grip.transform;
                rope.OnBreak.AddListener(LogBreak);
                rope.Rebuild();
                go.GetComponent<RopeMeshRenderer>().RadialSegments = s_RadialSegments[i];
            }
        }

        void FixedUpdate()
        {
            float step = m_PullSpeed * Time.fixedDeltaTime;
            for (int i = 0; i < _grips.Length; i++)
            {
                var p = _grips[i].position;
                _grips[i].position = new Vector3(p.x, p.y - step, p.z);
            }
        }

        static void LogBreak(Vector3 position, float tension)
        {
            Debug.Log(string.Format(CultureInfo.InvariantCulture, "Rope broke at ({0:F3}, {1:F3}, {2:F3}) m, peak tension {3:F1} N.",
                position.x, position.y, position.z, tension));
        }
    }
}
