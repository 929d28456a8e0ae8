namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.ForceMode: use ForceMode to specify how to apply a force using Rigidbody.AddForce or ArticulationBody.AddForce.</summary>
    public enum ForceMode
    {
        /// <summary>Add a continuous force to the rigidbody, using its mass.</summary>
        Force = 0,
        /// <summary>Add an instant force impulse to the rigidbody, using its mass.</summary>
        Impulse = 1,
        /// <summary>Add an instant velocity change to the rigidbody, ignoring its mass.</summary>
        VelocityChange = 2,
        /// <summary>Add a continuous acceleration to the rigidbody, ignoring its mass.</summary>
        Acceleration = 5,
    }
}
