using System;
using UnityEngine;
using UnityEngine.Events;

namespace HookeRope
{
    /// <summary>Raised when the rope breaks: world position of the break in metres and the peak tension in newtons just before it.</summary>
    [Serializable]
    public sealed class RopeBreakUnityEvent : UnityEvent<Vector3, float>
    {
    }
}
