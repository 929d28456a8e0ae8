using System;
using System.Globalization;
using UnityEngine;

namespace HookeRope.Samples.FallArrest
{
    /// <summary>
    /// Fall Arrest sample: a 100 kg worker rig (Rigidbody capsule with a harness D-ring) on a 2 m lanyard falls
    /// 4 m before the lanyard goes taut and is arrested. After the arrest the console compares the peak arrest
    /// force with the limits of EN 355 (6 kN) and ANSI Z359.13 (8 kN) and with the massless-lanyard estimate
    /// F = M·g + sqrt((M·g)² + 2·M·g·k·h), k = E·A/L. Beside it (3 m along z) the same fall of a worker rig without
    /// a Rigidbody: a CharacterController the lanyard carries as a 100 kg rig mass (<see cref="FallArrestCharacterWorker"/>),
    /// as a VR or character rig would be. Everything is built in code in Start.
    /// </summary>
    public sealed class FallArrestBootstrap : MonoBehaviour
    {
        const float Gravity = 9.81f;

        [SerializeField, Tooltip("Worker mass M (kg).")]
        float m_WorkerMass = 100f;

        [SerializeField, Tooltip("Lanyard rest length L (m).")]
        float m_LanyardLength = 2f;

        [SerializeField, Tooltip("Free fall h before the lanyard goes taut (m), at most 2·L (the worker starts above the anchor).")]
        float m_FreeFall = 4f;

        [SerializeField, Tooltip("Lanyard axial stiffness E·A (N). About 6 kN of E·A keeps a 4 m fall of 100 kg under EN 355's 6 kN.")]
        float m_AxialStiffness = 30000f;

        [SerializeField, Tooltip("Height of the anchor above the ground (m).")]
        float m_AnchorHeight = 9f;

        /// <summary>Distance along z (m) between the Rigidbody worker and the CharacterController worker.</summary>
        const float CharacterLaneZ = 3f;

        ElasticRope _lanyard, _characterLanyard;
        float _elapsed;
        bool _reported;

        void OnValidate()
        {
            m_WorkerMass = Math.Max(1f, m_WorkerMass);
            m_LanyardLength = Math.Max(0.1f, m_LanyardLength);
            m_FreeFall = Math.Min(Math.Max(0f, m_FreeFall), 2f * m_LanyardLength);
            m_AxialStiffness = Math.Max(1f, m_AxialStiffness);
        }

        void Start()
        {
            var ground = GameObject.CreatePrimitive(PrimitiveType.Plane);
            ground.name = "Ground";
            ground.transform.localScale = new Vector3(2f, 1f, 2f);

            // the Rigidbody worker
            var dRing = BuildWorker("Worker", 0f);
            var body = dRing.parent.gameObject.AddComponent<Rigidbody>();
            body.mass = m_WorkerMass;
            body.constraints = RigidbodyConstraints.FreezeRotation;
            body.interpolation = RigidbodyInterpolation.Interpolate; // drawn smoothly between fixed steps
            _lanyard = BuildLanyard("Lanyard", BuildAnchor("Anchor", 0f));
            _lanyard.EndAttachment.Body = body;
            _lanyard.EndAttachment.Point = dRing;
            _lanyard.Rebuild();

            // the CharacterController worker: no Rigidbody; the lanyard carries its mass and tells it where to move
            var characterDRing = BuildWorker("Worker (CharacterController)", CharacterLaneZ);
            var rig = characterDRing.parent.gameObject;
            Destroy(rig.GetComponent<CapsuleCollider>());   // the controller is the rig's capsule
            rig.AddComponent<CharacterController>().minMoveDistance = 0f;
            _characterLanyard = BuildLanyard("Lanyard (CharacterController)", BuildAnchor("Anchor (CharacterController)", CharacterLaneZ));
            _characterLanyard.EndAttachment.Point = characterDRing;
            _characterLanyard.EndAttachment.RigMass = m_WorkerMass;
            _characterLanyard.Rebuild();
            rig.AddComponent<FallArrestCharacterWorker>().Lanyard = _characterLanyard;
        }

        /// <summary>
        /// The anchor ring stands 5 cm off a wall plate (a 20 cm cube whose face is at x = −0.05 m); the lanyard is tied
        /// to the ring. Returns the ring.
        /// </summary>
        Transform BuildAnchor(string name, float z)
        {
            var plate = GameObject.CreatePrimitive(PrimitiveType.Cube);
            plate.name = name + " Plate";
            plate.transform.position = new Vector3(-0.15f, m_AnchorHeight, z);
            plate.transform.localScale = new Vector3(0.2f, 0.2f, 0.2f);
            var anchor = new GameObject(name);
            anchor.transform.position = new Vector3(0f, m_AnchorHeight, z);
            return anchor.transform;
        }

        /// <summary>
        /// Capsule primitive: 2 m tall, 0.5 m radius. The harness D-ring sits on its side 0.7 m above its centre,
        /// straight above the anchor ring: the worker falls past the plate with 5 cm to spare and the lanyard pulls
        /// straight up (a free fall of exactly m_FreeFall before it goes taut). Returns the D-ring.
        /// </summary>
        Transform BuildWorker(string name, float z)
        {
            var worker = GameObject.CreatePrimitive(PrimitiveType.Capsule);
            worker.name = name;
            float dRingHeight = m_AnchorHeight + (m_FreeFall - m_LanyardLength);
            worker.transform.position = new Vector3(0.5f, dRingHeight - 0.7f, z);
            var dRing = new GameObject("Harness D-Ring");
            dRing.transform.SetParent(worker.transform, false);
            dRing.transform.localPosition = new Vector3(-0.5f, 0.7f, 0f);
            return dRing.transform;
        }

        ElasticRope BuildLanyard(string name, Transform anchor)
        {
            var lanyard = new GameObject(name, typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
            lanyard.transform.position = anchor.position;
            var rope = lanyard.GetComponent<ElasticRope>();
            rope.RestLength = m_LanyardLength;
            rope.Radius = 0.01f;
            rope.AxialStiffness = m_AxialStiffness;
            rope.SegmentCount = 20;
            rope.Substeps = 8;
            rope.Fracture = false;
            rope.StartAttachment.Point = anchor;
            return rope;
        }

        void FixedUpdate()
        {
            if (_lanyard == null || _reported) return;
            _elapsed += Time.fixedDeltaTime;
            if (_elapsed < 4f) return;
            _reported = true;

            float weight = m_WorkerMass * Gravity;
            float k = m_AxialStiffness / m_LanyardLength;
            float estimate = weight + MathF.Sqrt(weight * weight + 2f * weight * k * m_FreeFall);
            float peak = _lanyard.PeakArrestForce;
            Debug.Log(string.Format(CultureInfo.InvariantCulture,
                "Fall arrest: peak arrest force {0:F0} N (massless-lanyard estimate {1:F0} N). EN 355 (6 kN): {2}. ANSI Z359.13 (8 kN): {3}. CharacterController worker: {4:F0} N.",
                peak, estimate, _lanyard.MeetsEn355 ? "within" : "EXCEEDED", _lanyard.MeetsAnsiZ359_13 ? "within" : "EXCEEDED",
                _characterLanyard.PeakArrestForce));
        }
    }
}
