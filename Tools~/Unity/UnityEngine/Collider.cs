namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Collider: a base class of all colliders.</summary>
    public class Collider : Component
    {
        /// <summary>Enabled Colliders will collide with other Colliders, disabled Colliders won't.</summary>
        public bool enabled { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The rigidbody the collider is attached to.</summary>
        public Rigidbody attachedRigidbody => throw Shim.NotRun;

        /// <summary>Specify if this collider is configured as a trigger.</summary>
        public bool isTrigger { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
