using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the script assemblies Unity's TypeCache would see — every assembly that is, or references,
    /// the stand-in's UnityEngine or UnityEditor — including those not yet loaded by .NET (Unity loads every script
    /// assembly up front; .NET loads an assembly only when code first needs it, so referenced assemblies are loaded
    /// here, and so are the other assemblies beside the application that reference UnityEngine or UnityEditor, the
    /// stand-in's "project"). Types that fail to load are skipped.
    /// </summary>
    internal static class ScriptAssemblies
    {
        static readonly object s_Lock = new object();
        static int s_Seen = -1;
        static Type[] s_Types = Array.Empty<Type>();

        /// <summary>The types of all script assemblies.</summary>
        internal static Type[] Types()
        {
            lock (s_Lock)
            {
                LoadReferences();
                var loaded = AppDomain.CurrentDomain.GetAssemblies();
                if (loaded.Length == s_Seen) return s_Types;
                var types = new List<Type>();
                foreach (var assembly in loaded.Where(IsScriptAssembly))
                {
                    try { types.AddRange(assembly.GetTypes()); }
                    catch (ReflectionTypeLoadException e) { types.AddRange(e.Types.Where(t => t != null)); }
                }
                s_Seen = loaded.Length;
                s_Types = types.ToArray();
                return s_Types;
            }
        }

        static bool IsScriptAssembly(Assembly assembly)
        {
            if (assembly.IsDynamic) return false;
            string name = assembly.GetName().Name;
            if (name == "UnityEngine" || name == "UnityEditor") return true;
            return assembly.GetReferencedAssemblies().Any(r => r.Name == "UnityEngine" || r.Name == "UnityEditor");
        }

        static bool s_LoadedFolder;

        static void LoadReferences()
        {
            if (!s_LoadedFolder)
            {
                s_LoadedFolder = true;
                LoadApplicationFolder();
            }
            var pending = new Queue<Assembly>(AppDomain.CurrentDomain.GetAssemblies().Where(IsScriptAssembly));
            var seen = new HashSet<string>(AppDomain.CurrentDomain.GetAssemblies().Select(a => a.GetName().Name));
            while (pending.Count > 0)
            {
                foreach (var reference in pending.Dequeue().GetReferencedAssemblies())
                {
                    if (!seen.Add(reference.Name)) continue;
                    Assembly loaded;
                    try { loaded = Assembly.Load(reference); }
                    catch (Exception e) when (e is System.IO.FileNotFoundException || e is System.IO.FileLoadException || e is BadImageFormatException) { continue; }
                    if (IsScriptAssembly(loaded)) pending.Enqueue(loaded);
                }
            }
        }

        static void LoadApplicationFolder()
        {
            string folder = AppContext.BaseDirectory;
            if (string.IsNullOrEmpty(folder) || !System.IO.Directory.Exists(folder)) return;
            var loaded = new HashSet<string>(AppDomain.CurrentDomain.GetAssemblies().Select(a => a.GetName().Name));
            foreach (string file in System.IO.Directory.GetFiles(folder, "*.dll"))
            {
                string name = System.IO.Path.GetFileNameWithoutExtension(file);
                if (loaded.Contains(name) || name.StartsWith("System.", StringComparison.Ordinal) || name.StartsWith("Microsoft.", StringComparison.Ordinal) ||
                    name.StartsWith("nunit", StringComparison.OrdinalIgnoreCase) || name.StartsWith("NUnit3", StringComparison.Ordinal) || name.StartsWith("testhost", StringComparison.Ordinal))
                    continue;
                try { Assembly.Load(AssemblyName.GetAssemblyName(file)); }
                catch (Exception e) when (e is System.IO.FileNotFoundException || e is System.IO.FileLoadException || e is BadImageFormatException) { }
            }
        }
    }
}