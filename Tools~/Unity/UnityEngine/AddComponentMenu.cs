namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.AddComponentMenu: places the script in the component menu.</summary>
    public sealed class AddComponentMenu : System.Attribute
    {
        /// <summary>Add an item in the Component menu.</summary>
        public AddComponentMenu(string menuName) { }
    }
}
