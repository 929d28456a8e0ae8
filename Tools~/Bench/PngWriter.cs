using System;
using System.IO;
using System.IO.Compression;

namespace HookeRope.Bench
{
    /// <summary>Minimal RGBA8 PNG encoder (zlib stream via DeflateStream, CRC-32 and Adler-32 computed here).</summary>
    internal static class PngWriter
    {
        /// <summary>PNG bytes of an RGBA32 image; <paramref name="bottomUp"/> = row 0 of the input is the bottom row (Unity order).</summary>
        public static byte[] Encode(int width, int height, byte[] rgba, bool bottomUp)
        {
            var raw = new byte[height * (width * 4 + 1)];
            for (int row = 0; row < height; row++)
            {
                int source = bottomUp ? height - 1 - row : row;
                raw[row * (width * 4 + 1)] = 0;
                Buffer.BlockCopy(rgba, source * width * 4, raw, row * (width * 4 + 1) + 1, width * 4);
            }
            var zlib = new MemoryStream();
            zlib.WriteByte(0x78); zlib.WriteByte(0x9C);
            using (var deflate = new DeflateStream(zlib, CompressionLevel.Optimal, true)) deflate.Write(raw, 0, raw.Length);
            WriteBigEndian(zlib, Adler32(raw));

            var png = new MemoryStream();
            png.Write(new byte[] { 137, 80, 78, 71, 13, 10, 26, 10 }, 0, 8);
            var header = new MemoryStream();
            WriteBigEndian(header, (uint)width);
            WriteBigEndian(header, (uint)height);
            header.Write(new byte[] { 8, 6, 0, 0, 0 }, 0, 5);
            Chunk(png, "IHDR", header.ToArray());
            Chunk(png, "IDAT", zlib.ToArray());
            Chunk(png, "IEND", Array.Empty<byte>());
            return png.ToArray();
        }

        private static void Chunk(Stream s, string type, byte[] data)
        {
            WriteBigEndian(s, (uint)data.Length);
            var typed = new byte[4 + data.Length];
            for (int i = 0; i < 4; i++) typed[i] = (byte)type[i];
            Buffer.BlockCopy(data, 0, typed, 4, data.Length);
            s.Write(typed, 0, typed.Length);
            WriteBigEndian(s, Crc32(typed));
        }

        private static void WriteBigEndian(Stream s, uint v)
        {
            s.WriteByte((byte)(v >> 24)); s.WriteByte((byte)(v >> 16)); s.WriteByte((byte)(v >> 8)); s.WriteByte((byte)v);
        }

        private static uint Crc32(byte[] data)
        {
            uint crc = 0xFFFFFFFFu;
            foreach (byte b in data)
            {
                crc ^= b;
                for (int k = 0; k < 8; k++) crc = (crc & 1u) != 0 ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
            }
            return ~crc;
        }

        private static uint Adler32(byte[] data)
        {
            uint a = 1, b = 0;
            foreach (byte d in data) { a = (a + d) % 65521u; b = (b + a) % 65521u; }
            return (b << 16) | a;
        }
    }
}
