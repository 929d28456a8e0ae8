using System;
using UnityEngine;

namespace HookeRope
{
    // Live edits during Play (issue 13 item 4): every serialized field takes effect at the next Simulate.
    public sealed partial class ElasticRope
    {
        // What the core rope was built from, for the fields the core cannot change in place. Compared at the start
        // of every step (allocation-free), so edits from code (RopeEnd.Point/Body, array elements) and from the
        // inspector (SerializedObject, OnValidate) rebuild at the next step.
        Transform _builtStartPoint, _builtEndPoint;
        Rigidbody _builtStartBody, _builtEndBody;
        float _builtStartRigMass, _builtEndRigMass;
        RopeCollisionMode _builtCollisionMode;
        int _builtLayers;
        float _builtFriction, _builtCompliance;
        Collider[] _builtColliders = Array.Empty<Collider>();
        Transform[] _builtPlanes = Array.Empty<Transform>();

        /// <summary>Records the rebuild-only fields the core rope was just built from.</summary>
        void RecordBuiltTopology()
        {
            _builtStartPoint = m_Start.Point; _builtStartBody = m_Start.Body;
            _builtEndPoint = m_End.Point; _builtEndBody = m_End.Body;
            _builtStartRigMass = m_Start.RigMass; _builtEndRigMass = m_End.RigMass;
            _builtCollisionMode = m_CollisionMode;
            _builtLayers = m_CollisionLayers.value;
            _builtFriction = m_Friction;
            _builtCompliance = m_AttachmentCompliance;
            _builtColliders = m_Colliders == null ? Array.Empty<Collider>() : (Collider[])m_Colliders.Clone();
            _builtPlanes = m_Planes == null ? Array.Empty<Transform>() : (Transform[])m_Planes.Clone();
        }

        /// <summary>
        /// True when a field the core cannot change in place differs from what the rope was built from: segment
        /// count, radius model on/off, an end's Point, Body or RigMass, collision mode, layers, friction, colliders, planes,
        /// attachment compliance. Allocation-free.
        /// </summary>
        bool TopologyChanged()
        {
            if (_rope.SegmentCount != m_SegmentCount) return true;
            if ((_simulation.RadiusSettings != null) != RadiusFeaturesOn) return true;
            if (m_Start == null || m_End == null) return false;
            if (m_Start.Point != _builtStartPoint || m_Start.Body != _builtStartBody) return true;
            if (m_End.Point != _builtEndPoint || m_End.Body != _builtEndBody) return true;
            if (m_Start.RigMass != _builtStartRigMass || m_End.RigMass != _builtEndRigMass) return true;
            if (m_CollisionMode != _builtCollisionMode || m_CollisionLayers.value != _builtLayers) return true;
            if (m_Friction != _builtFriction || m_AttachmentCompliance != _builtCompliance) return true;
            return !SameElements(m_Colliders, _builtColliders) || !SameElements(m_Planes, _builtPlanes);
        }

        static bool SameElements<T>(T[] current, T[] built) where T : UnityEngine.Object
        {
            int n = current?.Length ?? 0;
            if (n != built.Length) return false;
            for (int i = 0; i < n; i++)
                if (current[i] != built[i]) return false;
            return true;
        }
    }
}
