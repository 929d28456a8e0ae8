using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Builds test objects for the edit-mode component tests and destroys them afterwards. Switches physics to
    /// script simulation so a test can advance rope and Rigidbodies together with fixed steps, and restores it.
    /// </summary>
    sealed class UnityRopeScene
    {
        readonly List<GameObject> _objects = new List<GameObject>();
        SimulationMode _savedMode;

        /// <summary>Takes over the physics clock (Physics.simulationMode = Script).</summary>
        public void Begin()
        {
            _savedMode = Physics.simulationMode;
            Physics.simulationMode = SimulationMode.Script;
        }

        /// <summary>Destroys every object created here and gives the physics clock back.</summary>
        public void End()
        {
            for (int i = _objects.Count - 1; i >= 0; i--)
                if (_objects[i] != null) Object.DestroyImmediate(_objects[i]);
            _objects.Clear();
            Physics.simulationMode = _savedMode;
        }

        /// <summary>An empty object at <paramref name="position"/> (m).</summary>
        public Transform Point(string name, Vector3 position)
        {
            var go = Track(new GameObject(name));
            go.transform.position = position;
            return go.transform;
        }

        /// <summary>A Rigidbody of <paramref name="mass"/> kg at <paramref name="position"/> (m), gravity on.</summary>
        public Rigidbody Body(string name, Vector3 position, float mass)
        {
            var go = Track(new GameObject(name));
            go.transform.position = position;
            var body = go.AddComponent<Rigidbody>();
            body.mass = mass;
            body.useGravity = true;
            return body;
        }

        /// <summary>A rope object with ElasticRope (not built yet: the caller configures it, then calls Rebuild()).</summary>
        public ElasticRope Rope(string name, Vector3 position)
        {
            var go = Track(new GameObject(name));
            go.transform.position = position;
            return go.AddComponent<ElasticRope>();
        }

        /// <summary>Registers an object created elsewhere for clean-up.</summary>
        public GameObject Track(GameObject go)
        {
            _objects.Add(go);
            return go;
        }

        /// <summary>Advances rope and physics together by <paramref name="steps"/> steps of <paramref name="dt"/> seconds.</summary>
        public static void Run(ElasticRope rope, int steps, float dt)
        {
            for (int i = 0; i < steps; i++)
            {
                rope.Simulate(dt);
                Physics.Simulate(dt);
            }
        }

        /// <summary>
        /// A worker rig: a Rigidbody of <paramref name="mass"/> kg at <paramref name="position"/> (m) with a "Harness D-Ring"
        /// child at <paramref name="dRingOffset"/> (m, local).
        /// </summary>
        public Rigidbody Rig(Vector3 position, float mass, Vector3 dRingOffset, out Transform dRing)
        {
            var worker = Body("Worker", position, mass);
            dRing = new GameObject("Harness D-Ring").transform;
            dRing.SetParent(worker.transform, false);
            dRing.localPosition = dRingOffset;
            return worker;
        }
    }
}
