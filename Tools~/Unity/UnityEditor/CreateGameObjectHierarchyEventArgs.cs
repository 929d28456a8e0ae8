using System.Runtime.InteropServices;
using UnityEngine.SceneManagement;

namespace UnityEditor
{
    /// <summary>Data of a ObjectChangeKind.CreateGameObjectHierarchy event.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct CreateGameObjectHierarchyEventArgs
    {
        /// <summary>The instance id of the root GameObject of the created hierarchy.</summary>
        public int instanceId => m_InstanceId;

        /// <summary>The scene holding the GameObject (the stand-in: always the default Scene).</summary>
        public Scene scene => m_Scene;

        /// <summary>Makes the event data.</summary>
        public CreateGameObjectHierarchyEventArgs(int instanceId, Scene scene)
        {
            m_InstanceId = instanceId;
            m_Scene = scene;
        }

        private int m_InstanceId;
        private Scene m_Scene;
    }
}
