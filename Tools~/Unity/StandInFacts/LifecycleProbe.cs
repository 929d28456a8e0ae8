using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn.Facts
{
    /// <summary>A script that records every Unity message it receives, with the time it received it.</summary>
    sealed class LifecycleProbe : MonoBehaviour
    {
        public static readonly List<string> Calls = new List<string>();

        void Record(string message) => Calls.Add(name + "." + message);

        void Awake() => Record("Awake");
        void OnEnable() => Record("OnEnable");
        void Start() => Record("Start");
        void FixedUpdate() => Record("FixedUpdate@" + Time.fixedTime.ToString("F2", System.Globalization.CultureInfo.InvariantCulture));
        void Update() => Record("Update");
        void LateUpdate() => Record("LateUpdate");
        void OnDisable() => Record("OnDisable");
        void OnDestroy() => Record("OnDestroy");
    }

    /// <summary>A probe that also runs in Edit Mode.</summary>
    [ExecuteAlways]
    sealed class EditModeProbe : MonoBehaviour
    {
        public int Awakes, Updates;
        void Awake() => Awakes++;
        void Update() => Updates++;
    }

    /// <summary>A script that allows one instance per GameObject and needs a Rigidbody.</summary>
    [DisallowMultipleComponent, RequireComponent(typeof(Rigidbody))]
    sealed class SingleProbe : MonoBehaviour
    {
    }

    /// <summary>A script ordered before default-order scripts by [DefaultExecutionOrder].</summary>
    [DefaultExecutionOrder(-100)]
    sealed class EarlyProbe : MonoBehaviour
    {
        void FixedUpdate() => LifecycleProbe.Calls.Add(name + ".Early.FixedUpdate");
        void Update() => LifecycleProbe.Calls.Add(name + ".Early.Update");
    }

    /// <summary>A script ordered after default-order scripts by [DefaultExecutionOrder].</summary>
    [DefaultExecutionOrder(100)]
    sealed class LateProbe : MonoBehaviour
    {
        void FixedUpdate() => LifecycleProbe.Calls.Add(name + ".Late.FixedUpdate");
        void Update() => LifecycleProbe.Calls.Add(name + ".Late.Update");
    }
}
