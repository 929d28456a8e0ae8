using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Texture: base class for Texture handling. Sampler state (wrap, filter, aniso) is
    /// recorded; defaults are those of a texture created from script (Repeat, Bilinear, aniso 1).
    /// </summary>
    public class Texture : Object
    {
        TextureWrapMode m_WrapU = TextureWrapMode.Repeat, m_WrapV = TextureWrapMode.Repeat, m_WrapW = TextureWrapMode.Repeat;
        FilterMode m_FilterMode = FilterMode.Bilinear;
        int m_AnisoLevel = 1;

        /// <summary>Textures are created through their subclasses.</summary>
        protected Texture() { }

        /// <summary>Width of the Texture in pixels (Read Only; setting it is not implemented on this texture type, as in Unity).</summary>
        public virtual int width
        {
            get => throw StandInError.Unsupported(GetType().Name + ".width");
            set => throw new System.NotImplementedException();
        }

        /// <summary>Height of the Texture in pixels (Read Only; setting it is not implemented on this texture type, as in Unity).</summary>
        public virtual int height
        {
            get => throw StandInError.Unsupported(GetType().Name + ".height");
            set => throw new System.NotImplementedException();
        }

        /// <summary>How many mipmap levels are in this Texture (Read Only).</summary>
        public int mipmapCount
        {
            get { EnsureAlive(); return MipmapCountCore; }
        }

        /// <summary>Whether Unity stores an additional copy of this texture's pixel data in CPU-addressable memory.</summary>
        public virtual bool isReadable => throw StandInError.Unsupported(GetType().Name + ".isReadable");

        /// <summary>Texture coordinate wrapping mode (the getter returns the U mode; the setter sets U, V and W).</summary>
        public TextureWrapMode wrapMode
        {
            get { EnsureAlive(); return m_WrapU; }
            set
            {
                EnsureAlive();
                m_WrapU = m_WrapV = m_WrapW = value;
            }
        }

        /// <summary>Texture U coordinate wrapping mode.</summary>
        public TextureWrapMode wrapModeU { get { EnsureAlive(); return m_WrapU; } set { EnsureAlive(); m_WrapU = value; } }

        /// <summary>Texture V coordinate wrapping mode.</summary>
        public TextureWrapMode wrapModeV { get { EnsureAlive(); return m_WrapV; } set { EnsureAlive(); m_WrapV = value; } }

        /// <summary>Texture W coordinate wrapping mode for Texture3D.</summary>
        public TextureWrapMode wrapModeW { get { EnsureAlive(); return m_WrapW; } set { EnsureAlive(); m_WrapW = value; } }

        /// <summary>Filtering mode of the Texture.</summary>
        public FilterMode filterMode { get { EnsureAlive(); return m_FilterMode; } set { EnsureAlive(); m_FilterMode = value; } }

        /// <summary>Defines the anisotropic filtering level of the Texture.</summary>
        public int anisoLevel { get { EnsureAlive(); return m_AnisoLevel; } set { EnsureAlive(); m_AnisoLevel = value; } }

        /// <summary>Mip count of the concrete texture.</summary>
        internal virtual int MipmapCountCore => throw StandInError.Unsupported(GetType().Name + ".mipmapCount");

        /// <summary>Unity's exception for pixel access on a non-readable texture (Texture.cs, CreateNonReadableException).</summary>
        internal UnityException NonReadableException() =>
            new UnityException("Texture '" + NameCore + "' is not readable, the texture memory can not be accessed from scripts. You can make the texture readable in the Texture Import Settings.");
    }
}
