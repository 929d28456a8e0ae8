namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Behaviour.</summary>
    public class Behaviour : Component
    {
        /// <summary>Enabled Behaviours are Updated, disabled Behaviours are not.</summary>
        public bool enabled { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
