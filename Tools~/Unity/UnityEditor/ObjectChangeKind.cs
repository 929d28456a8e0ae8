namespace UnityEditor
{
    /// <summary>The kinds of change an ObjectChangeEventStream holds (values of UCR Editor/Mono/Undo/EditorObjectChangeEvents.cs, 2022.3).</summary>
    public enum ObjectChangeKind : ushort
    {
        /// <summary>An uninitialized value.</summary>
        None = 0,
        /// <summary>An open scene changed without more specific information.</summary>
        ChangeScene = 1,
        /// <summary>A GameObject was created, possibly with children (Undo.RegisterCreatedObjectUndo of a GameObject).</summary>
        CreateGameObjectHierarchy = 2,
        /// <summary>Anything in a sub-hierarchy may have changed.</summary>
        ChangeGameObjectStructureHierarchy = 3,
        /// <summary>Components of a GameObject were added, removed or changed.</summary>
        ChangeGameObjectStructure = 4,
        /// <summary>The parent of a GameObject changed (Undo.SetTransformParent).</summary>
        ChangeGameObjectParent = 5,
        /// <summary>A property of a GameObject or component changed.</summary>
        ChangeGameObjectOrComponentProperties = 6,
        /// <summary>A GameObject hierarchy will be destroyed after the callback.</summary>
        DestroyGameObjectHierarchy = 7,
        /// <summary>An asset object was created.</summary>
        CreateAssetObject = 8,
        /// <summary>An asset object will be destroyed after the callback.</summary>
        DestroyAssetObject = 9,
        /// <summary>A property of a loaded asset object changed.</summary>
        ChangeAssetObjectProperties = 10,
        /// <summary>An instance of a prefab was updated.</summary>
        UpdatePrefabInstances = 11,
        /// <summary>The order of a GameObject's children changed.</summary>
        ChangeChildrenOrder = 12,
    }
}
