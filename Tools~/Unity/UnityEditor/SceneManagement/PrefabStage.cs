using System;
using UnityEngine;

namespace UnityEditor.SceneManagement
{
    /// <summary>
    /// Stand-in of UnityEditor.SceneManagement.PrefabStage (UCR Editor/Mono/SceneManagement/StageManager/PrefabStage/
    /// PrefabStage.cs): the stage PrefabStageUtility.OpenPrefab opens, holding an editable copy of the prefab's contents.
    /// (**approx.**: the contents live in the stand-in's one scene, not in a separate preview scene.)
    /// </summary>
    public sealed class PrefabStage
    {
        readonly GameObject m_Root;
        readonly string m_AssetPath;

        internal PrefabStage(GameObject root, string assetPath)
        {
            m_Root = root;
            m_AssetPath = assetPath;
        }

        /// <summary>The root GameObject of the loaded Prefab Asset contents (throws once the stage is closed, as Unity does while it is unset).</summary>
        public GameObject prefabContentsRoot
        {
            get
            {
                if (m_Root == null) throw new InvalidOperationException("Requesting 'prefabContentsRoot' from Awake and OnEnable is not supported");
                return m_Root;
            }
        }

        /// <summary>The asset path of the Prefab being edited ("Packages/…/x.prefab").</summary>
        public string assetPath => m_AssetPath;

        /// <summary>Not Unity: destroys the contents (closing the stage without saving).</summary>
        internal void Close()
        {
            if (m_Root != null) UnityEngine.Object.DestroyImmediate(m_Root);
        }
    }
}
