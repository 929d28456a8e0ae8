using System;
using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn.Facts
{
    /// <summary>How a probe moves (an int-backed enum is serialized; a long-backed one is not).</summary>
    enum ProbeMode { A, B, C }

    /// <summary>A long-backed enum: Unity does not serialize it (EnumDataUtility marks 64-bit enums unserializable).</summary>
    enum ProbeWide : long { X, Y }

    /// <summary>A [Serializable] class held by value inside a script.</summary>
    [Serializable]
    sealed class ProbeEnd
    {
        public Transform point;
        [SerializeField] float m_Weight = 1f;
        [NonSerialized] public int runtimeTag = 7;

        public float Weight { get => m_Weight; set => m_Weight = value; }
    }

    /// <summary>A [Serializable] struct held by value inside a script.</summary>
    [Serializable]
    struct ProbePair
    {
        public int count;
        public Vector3 offset;
    }

    /// <summary>Base class whose serialized field Unity stores before the subclass's.</summary>
    class SerializationProbeBase : MonoBehaviour
    {
        [SerializeField] protected float m_BaseValue = 0.5f;
    }

    /// <summary>
    /// A script with one field of each serializable kind and one of each kind Unity skips. It also runs in Edit Mode,
    /// records what it saw in Awake and counts OnValidate calls (clamping m_Count to 0 or more there).
    /// </summary>
    [ExecuteAlways]
    sealed class SerializationProbe : SerializationProbeBase
    {
        public float speed = 1f;
        [SerializeField] int m_Count = 3;
        [SerializeField] ProbeMode m_Mode = ProbeMode.B;
        [SerializeField] string m_Label = "probe";
        [SerializeField] Vector3 m_Offset = new Vector3(1f, 2f, 3f);
        [SerializeField] Color m_Tint = new Color(1f, 0f, 0f, 1f);
        [SerializeField] LayerMask m_Mask = -1;
        [SerializeField] ProbeEnd m_End = new ProbeEnd();
        [SerializeField] ProbePair m_Pair;
        [SerializeField] Transform[] m_Points = Array.Empty<Transform>();
        [SerializeField] List<ProbeEnd> m_Ends = new List<ProbeEnd>();
        [SerializeField] GameObject m_Other;

        // Not serialized: static, const, readonly, [NonSerialized], private without [SerializeField], properties,
        // dictionaries, 64-bit enums.
#pragma warning disable CS0414
        static int s_Instances = 0;
#pragma warning restore CS0414
        public const int Version = 2;
        public readonly int fixedSeed = 11;
        [NonSerialized] public int runtimeCount = 5;
        int m_Private = 9;
        public int Property { get; set; } = 4;
        public Dictionary<string, int> table = new Dictionary<string, int>();
        public ProbeWide wide = ProbeWide.Y;

        public float SpeedInAwake = float.NaN;
        public int OnValidateCalls;

        public float BaseValue { get => m_BaseValue; set => m_BaseValue = value; }
        public int Count { get => m_Count; set => m_Count = value; }
        public ProbeMode Mode { get => m_Mode; set => m_Mode = value; }
        public string Label { get => m_Label; set => m_Label = value; }
        public Vector3 Offset { get => m_Offset; set => m_Offset = value; }
        public Color Tint { get => m_Tint; set => m_Tint = value; }
        public LayerMask Mask { get => m_Mask; set => m_Mask = value; }
        public ProbeEnd End { get => m_End; set => m_End = value; }
        public ProbePair Pair { get => m_Pair; set => m_Pair = value; }
        public Transform[] Points { get => m_Points; set => m_Points = value; }
        public List<ProbeEnd> Ends => m_Ends;
        public GameObject Other { get => m_Other; set => m_Other = value; }
        public int Private { get => m_Private; set => m_Private = value; }

        void Awake() => SpeedInAwake = speed;

        void OnValidate()
        {
            OnValidateCalls++;
            if (m_Count < 0) m_Count = 0;
        }
    }

    /// <summary>A ScriptableObject that counts its messages (counters not serialized).</summary>
    sealed class ProbeAsset : ScriptableObject
    {
        public float value = 1f;
        [NonSerialized] public int Awakes, Enables, Disables, Destroys;

        void Awake() => Awakes++;
        void OnEnable() => Enables++;
        void OnDisable() => Disables++;
        void OnDestroy() => Destroys++;
    }
}
