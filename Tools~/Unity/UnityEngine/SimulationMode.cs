namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.SimulationMode: a selection of modes that control when Unity executes the physics simulation.</summary>
    public enum SimulationMode
    {
        /// <summary>Execute the physics simulation immediately after the MonoBehaviour.FixedUpdate.</summary>
        FixedUpdate = 0,
        /// <summary>Execute the physics simulation immediately after MonoBehaviour.Update.</summary>
        Update = 1,
        /// <summary>Execute the physics simulation manually when you call Physics.Simulate.</summary>
        Script = 2,
    }
}
