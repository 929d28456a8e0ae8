using System;
using UnityEngine;

namespace UnityEditor.SceneManagement
{
    /// <summary>
    /// Stand-in of UnityEditor.SceneManagement.StageUtility (UCR …/StageManager/StageUtility.cs, MainStage.cs,
    /// PrefabStage.cs): the main stage and the prefab stage PrefabStageUtility opens.
    /// </summary>
    public static class StageUtility
    {
        /// <summary>Go to the main stage (closing the open prefab stage; the stand-in does not save it).</summary>
        public static void GoToMainStage() => PrefabStageUtility.CloseCurrent();

        /// <summary>
        /// Places the GameObject in the current stage: under an open prefab stage's contents root keeping its world pose
        /// (PrefabStage.PlaceGameObjectInStage: SetParent(root, true)); in the main stage a root object stays where it is,
        /// and an object with a parent is refused as Unity's MainStage does.
        /// </summary>
        public static void PlaceGameObjectInCurrentStage(GameObject gameObject)
        {
            if (gameObject is null) throw new ArgumentNullException(nameof(gameObject));
            var stage = PrefabStageUtility.GetCurrentPrefabStage();
            if (stage != null)
            {
                gameObject.transform.SetParent(stage.prefabContentsRoot.transform, true);
                return;
            }
            if (gameObject.transform.parent != null)
                throw new ArgumentException("GameObject has a transform parent, only root GameObjects are valid", "rootGameObject");
        }
    }
}
