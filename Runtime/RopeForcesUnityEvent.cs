using System;
using UnityEngine;
using UnityEngine.Events;

namespace HookeRope
{
    /// <summary>
    /// Raised after every rope step with the forces in newtons (world axes) the rope applied on its start and end
    /// attachments over that step (<see cref="ElasticRope.StartForce"/>, <see cref="ElasticRope.EndForce"/>).
    /// </summary>
    [Serializable]
    public sealed class RopeForcesUnityEvent : UnityEvent<Vector3, Vector3>
    {
    }
}
