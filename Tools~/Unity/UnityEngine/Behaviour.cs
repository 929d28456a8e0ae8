namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Behaviour.</summary>
    public class Behaviour : Component
    {
        /// <summary>Enabled Behaviours are Updated, disabled Behaviours are not.</summary>
        public bool enabled { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Reports whether a GameObject and its associated Behaviour is active and enabled.</summary>
        public bool isActiveAndEnabled => throw Shim.NotRun;
    }
}
