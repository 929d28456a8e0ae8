using System.Runtime.InteropServices;
using UnityEngine.SceneManagement;

namespace UnityEditor
{
    /// <summary>Data of a ObjectChangeKind.ChangeGameObjectParent event.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ChangeGameObjectParentEventArgs
    {
        /// <summary>The instance id of the GameObject whose parent changed.</summary>
        public int instanceId => m_InstanceId;

        /// <summary>The instance id of the previous parent's GameObject (0 when it was a root).</summary>
        public int previousParentInstanceId => m_PreviousParentInstanceId;

        /// <summary>The instance id of the new parent's GameObject (0 when it is now a root).</summary>
        public int newParentInstanceId => m_NewParentInstanceId;

        /// <summary>The scene the GameObject was in (the stand-in: always the default Scene).</summary>
        public Scene previousScene => m_PreviousScene;

        /// <summary>The scene the GameObject is in now (the stand-in: always the default Scene).</summary>
        public Scene newScene => m_NewScene;

        /// <summary>Makes the event data.</summary>
        public ChangeGameObjectParentEventArgs(int instanceId, Scene previousScene, int previousParentInstanceId, Scene newScene, int newParentInstanceId)
        {
            m_InstanceId = instanceId;
            m_PreviousParentInstanceId = previousParentInstanceId;
            m_NewParentInstanceId = newParentInstanceId;
            m_PreviousScene = previousScene;
            m_NewScene = newScene;
        }

        private int m_InstanceId;
        private int m_PreviousParentInstanceId;
        private int m_NewParentInstanceId;
        private Scene m_PreviousScene;
        private Scene m_NewScene;
    }
}
