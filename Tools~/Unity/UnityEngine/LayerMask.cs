namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.LayerMask: specifies Layers to use in a Physics.Raycast.</summary>
    public struct LayerMask
    {
        /// <summary>Converts a layer mask value to an integer value.</summary>
        public int value { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Implicitly converts a LayerMask to an integer.</summary>
        public static implicit operator int(LayerMask mask) => throw Shim.NotRun;

        /// <summary>Implicitly converts an integer to a LayerMask.</summary>
        public static implicit operator LayerMask(int intVal) => throw Shim.NotRun;
    }
}
