namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Rigidbody.</summary>
    public class Rigidbody : Component
    {
        /// <summary>The mass of the rigidbody.</summary>
        public float mass { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The velocity vector of the rigidbody. It represents the rate of change of Rigidbody position.</summary>
        public Vector3 velocity { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The position of the rigidbody.</summary>
        public Vector3 position { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Controls whether physics affects the rigidbody.</summary>
        public bool isKinematic { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Controls whether gravity affects this rigidbody.</summary>
        public bool useGravity { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Applies force at position. As a result this will apply a torque and force on the object.</summary>
        public void AddForceAtPosition(Vector3 force, Vector3 position, ForceMode mode = ForceMode.Force) => throw Shim.NotRun;

        /// <summary>The velocity of the rigidbody at the point worldPoint in global space.</summary>
        public Vector3 GetPointVelocity(Vector3 worldPoint) => throw Shim.NotRun;
    }
}
