using System;
using SkiaSharp;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// Reads a written figure back from its PNG: the rope's share of a pixel from its blue channel (the background is
    /// 0xF4F5F7, every shade of the orange rope has blue ≤ 31, so an edge pixel's blue is a linear mix), and whether a
    /// pixel is rope rather than background or grey prop (red clearly above blue).
    /// </summary>
    public sealed class RenderReadback : IDisposable
    {
        const float BackgroundBlue = 0xF7, RopeBlue = 20f;
        readonly SKBitmap bitmap;

        /// <summary>Decodes the PNG at <paramref name="path"/>.</summary>
        public RenderReadback(string path)
        {
            bitmap = SKBitmap.Decode(path) ?? throw new ArgumentException("not a PNG: " + path);
        }

        /// <summary>Image width (px).</summary>
        public int Width => bitmap.Width;
        /// <summary>Image height (px).</summary>
        public int Height => bitmap.Height;

        /// <summary>Share of pixel (x, y) covered by the rope over the background, 0 … 1 (clamped).</summary>
        public double RopeShare(int x, int y)
        {
            var c = bitmap.GetPixel(x, y);
            return Math.Clamp((BackgroundBlue - c.Blue) / (BackgroundBlue - RopeBlue), 0.0, 1.0);
        }

        /// <summary>True when pixel (x, y) is mostly rope (orange or its burr tint), not background or a grey prop.</summary>
        public bool IsRope(int x, int y)
        {
            var c = bitmap.GetPixel(x, y);
            return c.Red - c.Blue > 40;
        }

        /// <summary>Drawn width (px, fractional) of the rope in column <paramref name="x"/> between rows <paramref name="top"/> and <paramref name="bottom"/>.</summary>
        public double ColumnWidth(int x, int top, int bottom)
        {
            double sum = 0;
            for (int y = Math.Max(0, top); y <= Math.Min(Height - 1, bottom); y++) sum += RopeShare(x, y);
            return sum;
        }

        /// <summary>Runs of mostly-rope pixels (share ≥ 0.5) along row <paramref name="y"/>: start and length of each (px).</summary>
        public System.Collections.Generic.List<(int Start, int Length)> RowRuns(int y)
        {
            var runs = new System.Collections.Generic.List<(int, int)>();
            int start = -1;
            for (int x = 0; x <= Width; x++)
            {
                bool rope = x < Width && RopeShare(x, y) >= 0.5;
                if (rope && start < 0) start = x;
                if (!rope && start >= 0) { runs.Add((start, x - start)); start = -1; }
            }
            return runs;
        }

        /// <inheritdoc />
        public void Dispose() => bitmap.Dispose();
    }
}
