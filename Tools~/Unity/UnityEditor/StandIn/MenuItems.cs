using System;
using System.Collections.Generic;
using System.Reflection;
using UnityEditor;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the [MenuItem] methods of the loaded assemblies, for EditorApplication.ExecuteMenuItem
    /// (reference source Editor/Mono/EditorApplication.bindings.cs): the path is matched after dropping leading
    /// "/" and a trailing hotkey (" %g", " #&amp;x", " _g" …); a validate function runs first and can veto; the
    /// method gets a MenuCommand with a null context when it takes one.
    /// </summary>
    internal static class MenuItems
    {
        static Type[] s_Scanned;
        static List<(MenuItem Item, MethodInfo Method)> s_Items = new List<(MenuItem, MethodInfo)>();

        /// <summary>Runs the menu item at <paramref name="menuItemPath"/>; false when it is missing, fails validation or has an unusable signature.</summary>
        internal static bool Execute(string menuItemPath)
        {
            string path = Sanitize(menuItemPath);
            MethodInfo validate = null, execute = null;
            foreach (var (item, method) in Items())
            {
                if (WithoutHotkey(item.menuItem) != path) continue;
                if (item.validate) validate ??= method;
                else execute ??= method;
            }
            if (execute == null)
            {
                Debug.LogError("ExecuteMenuItem failed because there is no menu named '" + menuItemPath + "'");
                return false;
            }
            if (validate != null && !Invoke(validate, true)) return false;
            return Invoke(execute, false);
        }

        static bool Invoke(MethodInfo method, bool validate)
        {
            var parameters = method.GetParameters();
            object[] arguments;
            if (parameters.Length == 0) arguments = Array.Empty<object>();
            else if (parameters.Length == 1 && parameters[0].ParameterType == typeof(MenuCommand)) arguments = new object[] { new MenuCommand(null) };
            else return false;
            object result;
            try
            {
                result = method.Invoke(null, arguments);
            }
            catch (TargetInvocationException e)
            {
                Debug.LogException(e.InnerException ?? e);
                return !validate;
            }
            return !validate || result is true;
        }

        static string Sanitize(string path)
        {
            while (path.StartsWith("/", StringComparison.Ordinal)) path = path.Substring(1);
            while (path.Contains("//")) path = path.Replace("//", "/");
            return path;
        }

        /// <summary>The menu path without a trailing hotkey: a last space-separated token starting with %, #, &amp; or _.</summary>
        static string WithoutHotkey(string name)
        {
            int space = name.LastIndexOf(' ');
            if (space < 0 || space == name.Length - 1) return name;
            char first = name[space + 1];
            return first == '%' || first == '#' || first == '&' || first == '_' ? name.Substring(0, space).TrimEnd() : name;
        }

        static List<(MenuItem, MethodInfo)> Items()
        {
            var types = ScriptAssemblies.Types();
            if (ReferenceEquals(types, s_Scanned)) return s_Items;
            var items = new List<(MenuItem, MethodInfo)>();
            const BindingFlags Static = BindingFlags.Static | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly;
            foreach (var type in types)
            {
                try
                {
                    foreach (var method in type.GetMethods(Static))
                    foreach (MenuItem item in method.GetCustomAttributes(typeof(MenuItem), false))
                        items.Add((item, method));
                }
                catch (TypeLoadException) { }
            }
            s_Scanned = types;
            s_Items = items;
            return items;
        }
    }
}
