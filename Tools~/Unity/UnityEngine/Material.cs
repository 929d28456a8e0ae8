using System;
using System.Collections.Generic;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Material: a property sheet and keyword set on a Shader, recorded so tests can read back
    /// what was set. HasProperty answers from the shader's Properties block; values set for properties the shader
    /// lacks are stored silently (and read back); reading a property that neither was set nor exists in the shader
    /// logs Unity's "doesn't have a … property" error. renderQueue follows the Material.renderQueue documentation
    /// (-1 = the shader's queue; changing the shader resets it).
    /// </summary>
    public class Material : Object
    {
        const int UseShaderQueue = -1;

        Shader m_Shader;
        readonly Dictionary<string, float> m_Floats = new Dictionary<string, float>(StringComparer.Ordinal);
        readonly Dictionary<string, Color> m_Colors = new Dictionary<string, Color>(StringComparer.Ordinal);
        readonly Dictionary<string, Texture> m_Textures = new Dictionary<string, Texture>(StringComparer.Ordinal);
        readonly SortedSet<string> m_Keywords = new SortedSet<string>(StringComparer.Ordinal);
        int m_CustomRenderQueue = UseShaderQueue;

        /// <summary>Create a temporary Material from a Shader (ArgumentNullException when the shader is null).</summary>
        public Material(Shader shader)
        {
            if (shader == null) throw new ArgumentNullException(nameof(shader));
            m_Shader = shader;
        }

        /// <summary>Create a temporary Material by copying the shader and all properties (values, keywords, render queue) from the source Material.</summary>
        public Material(Material source)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            m_Shader = source.m_Shader;
            foreach (var pair in source.m_Floats) m_Floats[pair.Key] = pair.Value;
            foreach (var pair in source.m_Colors) m_Colors[pair.Key] = pair.Value;
            foreach (var pair in source.m_Textures) m_Textures[pair.Key] = pair.Value;
            m_Keywords.UnionWith(source.m_Keywords);
            m_CustomRenderQueue = source.m_CustomRenderQueue;
            name = source.name;
        }

        /// <summary>The shader used by the material. Assigning a different shader resets the render queue to the shader's.</summary>
        public Shader shader
        {
            get { EnsureAlive(); return m_Shader; }
            set
            {
                EnsureAlive();
                if (!ReferenceEquals(value, m_Shader)) m_CustomRenderQueue = UseShaderQueue;
                m_Shader = value;
            }
        }

        /// <summary>Render queue of this material: the value set, or the shader's render queue while it is -1.</summary>
        public int renderQueue
        {
            get
            {
                EnsureAlive();
                if (m_CustomRenderQueue != UseShaderQueue) return m_CustomRenderQueue;
                return m_Shader != null ? m_Shader.renderQueue : 2000;
            }
            set { EnsureAlive(); m_CustomRenderQueue = value; }
        }

        /// <summary>The main color: the shader's [MainColor] property, else "_Color".</summary>
        public Color color
        {
            get => GetColor(MainColorProperty);
            set => SetColor(MainColorProperty, value);
        }

        /// <summary>The main texture: the shader's [MainTexture] property, else "_MainTex".</summary>
        public Texture mainTexture
        {
            get => GetTexture(MainTextureProperty);
            set => SetTexture(MainTextureProperty, value);
        }

        /// <summary>Checks if material's shader has a property of a given name.</summary>
        public bool HasProperty(string name)
        {
            EnsureAlive();
            return m_Shader != null && m_Shader.Definition.Find(name) != null;
        }

        /// <summary>Sets a named float value.</summary>
        public void SetFloat(string name, float value)
        {
            EnsureAlive();
            m_Floats[RequireName(name)] = value;
        }

        /// <summary>Get a named float value.</summary>
        public float GetFloat(string name)
        {
            EnsureAlive();
            if (m_Floats.TryGetValue(RequireName(name), out float value)) return value;
            var property = m_Shader != null ? m_Shader.Definition.Find(name) : null;
            if (property != null && property.IsFloat) return property.DefaultFloat;
            LogMissing("float or range", name);
            return 0f;
        }

        /// <summary>Sets a named color value.</summary>
        public void SetColor(string name, Color value)
        {
            EnsureAlive();
            m_Colors[RequireName(name)] = value;
        }

        /// <summary>Get a named color value.</summary>
        public Color GetColor(string name)
        {
            EnsureAlive();
            if (m_Colors.TryGetValue(RequireName(name), out var value)) return value;
            var property = m_Shader != null ? m_Shader.Definition.Find(name) : null;
            if (property != null && property.IsColor) return property.DefaultColor;
            LogMissing("color", name);
            return new Color(0f, 0f, 0f, 0f);
        }

        /// <summary>Sets a named texture.</summary>
        public void SetTexture(string name, Texture value)
        {
            EnsureAlive();
            m_Textures[RequireName(name)] = value;
        }

        /// <summary>Get a named texture (null for an unassigned texture property).</summary>
        public Texture GetTexture(string name)
        {
            EnsureAlive();
            if (m_Textures.TryGetValue(RequireName(name), out var value)) return value;
            var property = m_Shader != null ? m_Shader.Definition.Find(name) : null;
            if (property == null || property.Kind != ShaderPropertyKind.Texture) LogMissing("texture", name);
            return null;
        }

        /// <summary>Enables a local shader keyword for this material.</summary>
        public void EnableKeyword(string keyword)
        {
            EnsureAlive();
            if (!string.IsNullOrEmpty(keyword)) m_Keywords.Add(keyword);
        }

        /// <summary>Disables a local shader keyword for this material.</summary>
        public void DisableKeyword(string keyword)
        {
            EnsureAlive();
            if (keyword != null) m_Keywords.Remove(keyword);
        }

        /// <summary>Checks whether a local shader keyword is enabled for this material.</summary>
        public bool IsKeywordEnabled(string keyword)
        {
            EnsureAlive();
            return keyword != null && m_Keywords.Contains(keyword);
        }

        /// <summary>An array containing names of the local shader keywords that are currently enabled for this material (ordinal order).</summary>
        public string[] shaderKeywords
        {
            get
            {
                EnsureAlive();
                var result = new string[m_Keywords.Count];
                m_Keywords.CopyTo(result);
                return result;
            }
            set
            {
                EnsureAlive();
                m_Keywords.Clear();
                if (value == null) return;
                for (int i = 0; i < value.Length; i++)
                    if (!string.IsNullOrEmpty(value[i])) m_Keywords.Add(value[i]);
            }
        }

        // ---- stand-in internals -------------------------------------------------------------------------------

        /// <summary>True when a value was set on this material for <paramref name="name"/> (any kind), whether or not the shader declares it.</summary>
        internal bool HasStoredValue(string name) =>
            name != null && (m_Floats.ContainsKey(name) || m_Colors.ContainsKey(name) || m_Textures.ContainsKey(name));

        /// <summary>The render queue as set (-1: the shader's).</summary>
        internal int RawRenderQueue => m_CustomRenderQueue;

        string MainColorProperty => m_Shader?.Definition.MainColor?.Name ?? "_Color";

        string MainTextureProperty => m_Shader?.Definition.MainTexture?.Name ?? "_MainTex";

        static string RequireName(string name) => name ?? throw new ArgumentNullException(nameof(name));

        void LogMissing(string kind, string property) =>
            Debug.LogError("Material '" + NameCore + "' with Shader '" + (m_Shader != null ? m_Shader.NameCore : "null") +
                           "' doesn't have a " + kind + " property '" + property + "'", this);
    }
}
