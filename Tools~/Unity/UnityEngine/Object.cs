// API shim: signatures copied from the Unity 2022.3 Scripting Reference. Bodies are never run.
namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Object.</summary>
    public class Object
    {
        /// <summary>The name of the object.</summary>
        public string name { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
