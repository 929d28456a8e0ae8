using UnityEngine;

namespace HookeRope
{
    // Self-wiring onto a harness rig (issue 13 item 1): see RopeAutoWiring.
    public sealed partial class ElasticRope
    {
        /// <summary>Add Component (and the inspector's Reset): a rope added inside a rig with a Rigidbody wires itself onto it.</summary>
        void Reset() => Wire(RopeAutoWiring.For(this));

        /// <summary>
        /// Play, from Awake before the build: the dropped-prefab case, a rope under a Rigidbody whose End has no Body,
        /// wires itself onto that body and logs one line naming what it wired.
        /// </summary>
        void WireOnDrop() => Wire(RopeAutoWiring.ForDrop(this));

        /// <summary>Carries out <paramref name="wiring"/> (<see cref="RopeAutoWiring"/>; null: nothing to wire) and logs what it did.</summary>
        void Wire(RopeAutoWiring wiring)
        {
            if (wiring == null) return;
            string line = wiring.WiredLine(); // before Apply: afterwards a new anchor reads as an existing one
            wiring.Apply();
            Debug.Log(line, this);
        }
    }
}
