namespace UnityEngine.SceneManagement
{
    /// <summary>
    /// Stand-in of UnityEngine.SceneManagement.Scene (UCR Runtime/Export/SceneManager/Scene.cs): only the type, so the
    /// editor's event-argument structs keep their 2022.3 signatures. The stand-in has one scene and models none of its
    /// members (a call does not compile); every event carries the default value.
    /// </summary>
    public partial struct Scene
    {
    }
}
