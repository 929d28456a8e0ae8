using System;
using System.Linq;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.MenuItem: adds a menu item that invokes the static method it marks (found by
    /// <see cref="EditorApplication.ExecuteMenuItem"/>). The name is normalized as Unity does (each "/"-separated part
    /// trimmed); the default priority is 10 for "GameObject/Create Other" items and 1000 otherwise.
    /// </summary>
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        /// <summary>Menu path of the item.</summary>
        public string menuItem;

        /// <summary>True for the validation function of the item.</summary>
        public bool validate;

        /// <summary>Priority of the item in its menu.</summary>
        public int priority;

        /// <summary>Creates a menu item and invokes the static function that follows it when the menu item is selected.</summary>
        public MenuItem(string itemName) : this(itemName, false) { }

        /// <summary>Creates a menu item (or its validation function when isValidateFunction).</summary>
        public MenuItem(string itemName, bool isValidateFunction)
            : this(itemName, isValidateFunction, itemName.StartsWith("GameObject/Create Other", StringComparison.Ordinal) ? 10 : 1000) { }

        /// <summary>Creates a menu item and invokes the static function that follows it when the menu item is selected.</summary>
        public MenuItem(string itemName, bool isValidateFunction, int priority)
        {
            menuItem = string.Join("/", itemName.Split('/').Select(part => part.Trim()));
            validate = isValidateFunction;
            this.priority = priority;
        }
    }
}
