namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.CollisionFlags: a bitmask returned by CharacterController.Move (UCR Modules/Physics/Managed/Dynamics.cs).</summary>
    public enum CollisionFlags
    {
        /// <summary>CollisionFlags is a bitmask returned by CharacterController.Move.</summary>
        None = 0,
        /// <summary>CollisionFlags is a bitmask returned by CharacterController.Move.</summary>
        Sides = 1,
        /// <summary>CollisionFlags is a bitmask returned by CharacterController.Move.</summary>
        Above = 2,
        /// <summary>CollisionFlags is a bitmask returned by CharacterController.Move.</summary>
        Below = 4,
        /// <summary>CollisionFlags is a bitmask returned by CharacterController.Move.</summary>
        CollidedSides = 1,
        /// <summary>CollisionFlags is a bitmask returned by CharacterController.Move.</summary>
        CollidedAbove = 2,
        /// <summary>CollisionFlags is a bitmask returned by CharacterController.Move.</summary>
        CollidedBelow = 4,
    }
}
