using System.IO;
using System.Runtime.InteropServices;
using SkiaSharp;

namespace HookeRope.Lab.Figures
{
    /// <summary>Writes the package's burr texture (<see cref="FigureTexture.PackageBurr"/>) as a PNG through SkiaSharp, top row = v = 1.</summary>
    public static class BurrTexturePng
    {
        /// <summary>File name inside the output folder.</summary>
        public const string FileName = "burr-texture.png";

        /// <summary>Writes the texture to <paramref name="path"/> (alpha kept, unpremultiplied); returns the file size in bytes.</summary>
        public static long Write(string path)
        {
            File.WriteAllBytes(path, Encode());
            return new FileInfo(path).Length;
        }

        /// <summary>
        /// The package's burr texture (level 0, 256 × 64) as PNG file bytes, RGBA with unpremultiplied alpha, the image's
        /// top row the texture's last (v = 1): the orientation of a glTF image, whose uv origin is its top-left corner.
        /// </summary>
        public static byte[] Encode()
        {
            var texture = FigureTexture.PackageBurr();
            int w = texture.Width, h = texture.Height;
            using (var bitmap = new SKBitmap(new SKImageInfo(w, h, SKColorType.Rgba8888, SKAlphaType.Unpremul)))
            {
                var rgba = texture.Rgba.ToArray();
                var pixels = bitmap.GetPixels();
                // the texture's row 0 is v = 0 (bottom); an image's row 0 is the top
                for (int y = 0; y < h; y++)
                    Marshal.Copy(rgba, (h - 1 - y) * w * 4, pixels + y * bitmap.RowBytes, w * 4);
                using (var data = bitmap.Encode(SKEncodedImageFormat.Png, 100))
                    return data.ToArray();
            }
        }
    }
}
