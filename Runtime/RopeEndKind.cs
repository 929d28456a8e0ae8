namespace HookeRope
{
    /// <summary>What one end of a rope is attached to.</summary>
    public enum RopeEndKind
    {
        /// <summary>Nothing: the end hangs free.</summary>
        Free,
        /// <summary>A Transform the end follows exactly (the rope cannot move it).</summary>
        Transform,
        /// <summary>A Rigidbody the rope pulls and is pulled by (two-way).</summary>
        Rigidbody,
        /// <summary>A rig without a Rigidbody at the Point (CharacterController, kinematic XR rig): the rope carries it as a load of RopeEnd.RigMass kg and reports where it must move.</summary>
        KinematicRig,
    }
}
