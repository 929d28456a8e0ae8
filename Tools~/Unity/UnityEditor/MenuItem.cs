using System;

namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.MenuItem: the MenuItem attribute allows you to add menu items to the main menu and Inspector context menus.</summary>
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        /// <summary>Creates a menu item and invokes the static function that follows it when the menu item is selected.</summary>
        public MenuItem(string itemName) { }

        /// <summary>Creates a menu item and invokes the static function that follows it when the menu item is selected.</summary>
        public MenuItem(string itemName, bool isValidateFunction, int priority) { }
    }
}
