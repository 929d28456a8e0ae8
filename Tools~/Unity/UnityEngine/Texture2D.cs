using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Texture2D: CPU pixel memory per mip level, uploaded by Apply into a recorded "GPU"
    /// copy. SetPixelData / Apply checks follow Unity 2022.3's Texture.cs (UnityException for a non-readable
    /// texture, a negative start index or no data) and the SetPixelData documentation (too little data for the mip
    /// level throws). Apply(…, makeNoLongerReadable: true) frees the CPU copy: isReadable is false afterwards.
    /// </summary>
    public sealed class Texture2D : Texture
    {
        readonly int m_Width, m_Height;
        readonly TextureFormat m_Format;
        readonly int m_MipCount;
        byte[][] m_Cpu;
        bool m_Readable = true;

        /// <summary>Create a new empty texture (mipChain: a full mip chain down to 1×1, else one level).</summary>
        public Texture2D(int width, int height, TextureFormat textureFormat, bool mipChain)
        {
            int bytesPerPixel = BytesPerPixel(textureFormat);
            if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
                throw new UnityException("Failed to create texture because of invalid parameters.");
            m_Width = width;
            m_Height = height;
            m_Format = textureFormat;
            m_MipCount = mipChain ? FullChain(width, height) : 1;
            m_Cpu = new byte[m_MipCount][];
            for (int mip = 0; mip < m_MipCount; mip++) m_Cpu[mip] = new byte[MipWidth(mip) * MipHeight(mip) * bytesPerPixel];
            Uploaded = new byte[m_MipCount][];
        }

        /// <summary>Width of the texture in pixels (Read Only).</summary>
        public override int width
        {
            get { EnsureAlive(); return m_Width; }
            set => throw new NotImplementedException();
        }

        /// <summary>Height of the texture in pixels (Read Only).</summary>
        public override int height
        {
            get { EnsureAlive(); return m_Height; }
            set => throw new NotImplementedException();
        }

        /// <summary>The format of the pixel data in the texture (Read Only).</summary>
        public TextureFormat format
        {
            get { EnsureAlive(); return m_Format; }
        }

        /// <summary>Whether the CPU copy of the pixel data exists (false after Apply(…, true)).</summary>
        public override bool isReadable
        {
            get { EnsureAlive(); return m_Readable; }
        }

        /// <summary>Set pixel values from raw preformatted data: fills mip level <paramref name="mipLevel"/> from element <paramref name="sourceDataStartIndex"/> on.</summary>
        public void SetPixelData<T>(T[] data, int mipLevel, int sourceDataStartIndex = 0)
        {
            EnsureAlive();
            if (sourceDataStartIndex < 0) throw new UnityException("SetPixelData: sourceDataStartIndex cannot be less than 0.");
            if (!m_Readable) throw NonReadableException();
            if (data == null || data.Length == 0) throw new UnityException("No texture data provided to SetPixelData.");
            if (mipLevel < 0 || mipLevel >= m_MipCount)
                throw new ArgumentException("The passed in miplevel " + mipLevel + " is invalid. It needs to be in the range 0 and " + (m_MipCount - 1));
            int elementSize = System.Runtime.InteropServices.Marshal.SizeOf(data[0]);
            long available = (long)(data.Length - Math.Min(sourceDataStartIndex, data.Length)) * elementSize;
            var destination = m_Cpu[mipLevel];
            if (available < destination.Length)
                throw new UnityException("SetPixelData: the data array (" + available + " bytes from index " + sourceDataStartIndex +
                                         ") is smaller than mip level " + mipLevel + " of the texture (" + destination.Length + " bytes).");
            RawBytes.CopyUnconstrained(data, sourceDataStartIndex * elementSize, destination, 0, destination.Length);
        }

        /// <summary>Copies changes you've made in a CPU texture to the GPU (recorded); makeNoLongerReadable frees the CPU copy.</summary>
        public void Apply(bool updateMipmaps = true, bool makeNoLongerReadable = false)
        {
            EnsureAlive();
            if (!m_Readable) throw NonReadableException();
            if (updateMipmaps) GenerateMips();
            for (int mip = 0; mip < m_MipCount; mip++) Uploaded[mip] = (byte[])m_Cpu[mip].Clone();
            ApplyCount++;
            LastApplyUpdatedMipmaps = updateMipmaps;
            if (makeNoLongerReadable)
            {
                m_Readable = false;
                m_Cpu = null;
            }
        }

        // ---- stand-in internals -------------------------------------------------------------------------------

        /// <summary>The pixel bytes of each mip level as of the last Apply (null entries before the first).</summary>
        internal byte[][] Uploaded { get; }

        /// <summary>How many times Apply ran.</summary>
        internal int ApplyCount { get; private set; }

        /// <summary>The updateMipmaps argument of the last Apply.</summary>
        internal bool LastApplyUpdatedMipmaps { get; private set; }

        internal override int MipmapCountCore => m_MipCount;

        /// <summary>Frees the CPU and uploaded pixel copies when the texture is destroyed.</summary>
        internal override void OnStandInDestroy()
        {
            m_Cpu = null;
            for (int mip = 0; mip < Uploaded.Length; mip++) Uploaded[mip] = null;
            base.OnStandInDestroy();
        }

        /// <summary>Bytes per pixel of the formats in the stand-in's subset.</summary>
        internal static int BytesPerPixel(TextureFormat format)
        {
            switch (format)
            {
                case TextureFormat.Alpha8: return 1;
                case TextureFormat.RGB24: return 3;
                case TextureFormat.RGBA32:
                case TextureFormat.ARGB32: return 4;
                default: throw StandInError.Unsupported("Texture2D with TextureFormat " + format);
            }
        }

        int MipWidth(int mip) => Math.Max(1, m_Width >> mip);

        int MipHeight(int mip) => Math.Max(1, m_Height >> mip);

        static int FullChain(int width, int height)
        {
            int levels = 1;
            for (int size = Math.Max(width, height); size > 1; size >>= 1) levels++;
            return levels;
        }

        /// <summary>Box-filters each mip level from the one above (per byte channel; Unity's own filter is not specified).</summary>
        void GenerateMips()
        {
            int bpp = BytesPerPixel(m_Format);
            for (int mip = 1; mip < m_MipCount; mip++)
            {
                int w = MipWidth(mip), h = MipHeight(mip), pw = MipWidth(mip - 1), ph = MipHeight(mip - 1);
                var src = m_Cpu[mip - 1];
                var dst = m_Cpu[mip];
                for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++)
                for (int c = 0; c < bpp; c++)
                {
                    int sum = 0, n = 0;
                    for (int dy = 0; dy < 2; dy++)
                    for (int dx = 0; dx < 2; dx++)
                    {
                        int sx = Math.Min(pw - 1, 2 * x + dx), sy = Math.Min(ph - 1, 2 * y + dy);
                        sum += src[(sy * pw + sx) * bpp + c];
                        n++;
                    }
                    dst[(y * w + x) * bpp + c] = (byte)((sum + n / 2) / n);
                }
            }
        }
    }
}
