using UnityEngine;

namespace HookeRope
{
    // Self-wiring onto a harness rig (issue 13 item 1): see RopeAutoWiring.
    public sealed partial class ElasticRope
    {
        /// <summary>Add Component (and the inspector's Reset): a rope added inside a rig with a Rigidbody wires itself onto it.</summary>
        void Reset()
        {
            WireOntoRig();
        }

        /// <summary>
        /// Play, from Awake before the build: the dropped-prefab case, a rope under a Rigidbody whose End has no Body,
        /// wires itself onto that body and logs one line naming what it wired.
        /// </summary>
        void WireOnDrop()
        {
            if (m_End.Body == null && GetComponentInParent<Rigidbody>() != null) WireOntoRig();
        }

        /// <summary>Wires this rope onto its rig when it has one and is not wired yet (<see cref="RopeAutoWiring"/>); logs what it did.</summary>
        void WireOntoRig()
        {
            var wiring = RopeAutoWiring.For(this);
            if (wiring == null) return;
            string line = "HookeRope wired onto the rig: " + wiring.Describe(); // before Apply: afterwards a new anchor reads as an existing one
            wiring.Apply();
            Debug.Log(line, this);
        }
    }
}
