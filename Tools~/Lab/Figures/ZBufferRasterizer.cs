using System;
using System.Collections.Generic;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// A small depth-buffered rasterizer for the documentation figures: flat-shaded triangles (one colour per triangle from
    /// its normal and a light fixed to the camera), a per-pixel depth test (no painter's-order artefacts), an optional colour map per triangle (the burr texture, affine
    /// uv: exact for the orthographic camera), and a per-pixel
    /// record of which <see cref="SurfaceKind"/> is visible. Samples at pixel centres; the caller supersamples for smooth edges.
    /// </summary>
    public sealed class ZBufferRasterizer
    {
        /// <summary>Share of the base colour every lit or unlit face keeps (ambient).</summary>
        public const float Ambient = 0.4f;

        readonly OrthographicView view;
        readonly float[] depth;
        readonly Float3 light;

        /// <summary>
        /// Added to each textured triangle's level of detail (log2 of texels per sample): log2 of the caller's supersampling,
        /// so the mip level is the one a GPU picks for the final pixel (multisampling shades once per pixel). 0 by default.
        /// </summary>
        public float LodBias { get; set; }

        /// <summary>
        /// Samples per side of the block a texture is read once for (1 = every sample; the caller's supersampling = once per
        /// final pixel, as a GPU with multisampling shades: coverage per sample, texture at the pixel centre).
        /// </summary>
        public int ShadingRate { get; set; } = 1;

        /// <summary>Visible colour per pixel, 0xRRGGBB, row-major from the top-left.</summary>
        public uint[] Color { get; }

        /// <summary>Visible surface kind per pixel.</summary>
        public SurfaceKind[] Kind { get; }

        /// <summary>An empty frame of the view's size filled with <paramref name="background"/> (0xRRGGBB).</summary>
        public ZBufferRasterizer(OrthographicView view, uint background)
        {
            this.view = view ?? throw new ArgumentNullException(nameof(view));
            int n = view.Width * view.Height;
            depth = new float[n];
            Color = new uint[n];
            Kind = new SurfaceKind[n];
            Array.Fill(depth, float.PositiveInfinity);
            Array.Fill(Color, background);
            light = (view.TowardCamera * 0.7f + view.Up * 0.6f - view.Right * 0.4f).NormalizedOr(view.TowardCamera);
        }

        /// <summary>Draws every triangle of <paramref name="triangles"/>.</summary>
        public void Draw(IReadOnlyList<SceneTriangle> triangles)
        {
            for (int i = 0; i < triangles.Count; i++) Draw(triangles[i]);
        }

        /// <summary>Number of pixels where <paramref name="kind"/> is visible.</summary>
        public int CountVisible(SurfaceKind kind)
        {
            int count = 0;
            foreach (var k in Kind) if (k == kind) count++;
            return count;
        }

        /// <summary>The flat-shaded colour of a face with unit normal <paramref name="normal"/> (0xRRGGBB).</summary>
        public uint Shade(uint color, Float3 normal) => Tint(color, Lighting(normal), 1f, 1f, 1f);

        /// <summary>Brightness factor (unitless, <see cref="Ambient"/> … 1) of a face with unit normal <paramref name="normal"/>.</summary>
        public float Lighting(Float3 normal) => Ambient + (1f - Ambient) * Math.Max(0f, Float3.Dot(normal, light));

        /// <summary><paramref name="color"/> (0xRRGGBB) times <paramref name="lit"/> times a texel (r, g, b in [0, 1]).</summary>
        static uint Tint(uint color, float lit, float r, float g, float b)
        {
            uint cr = Channel(color >> 16, lit * r), cg = Channel(color >> 8, lit * g), cb = Channel(color, lit * b);
            return (cr << 16) | (cg << 8) | cb;
        }

        static uint Channel(uint value, float scale) => (uint)Math.Min(255f, (value & 0xFF) * scale + 0.5f);

        /// <summary>Rasterizes one triangle with the depth test (both windings are drawn; hidden faces lose the test).</summary>
        public void Draw(in SceneTriangle t)
        {
            var (ax, ay, az) = view.Project(t.A);
            var (bx, by, bz) = view.Project(t.B);
            var (cx, cy, cz) = view.Project(t.C);
            float area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
            if (!(Math.Abs(area) > 1e-12f)) return;
            int x0 = Math.Max(0, (int)Math.Floor(Math.Min(ax, Math.Min(bx, cx))));
            int x1 = Math.Min(view.Width - 1, (int)Math.Ceiling(Math.Max(ax, Math.Max(bx, cx))));
            int y0 = Math.Max(0, (int)Math.Floor(Math.Min(ay, Math.Min(by, cy))));
            int y1 = Math.Min(view.Height - 1, (int)Math.Ceiling(Math.Max(ay, Math.Max(by, cy))));
            if (x0 > x1 || y0 > y1) return;
            float lit = Lighting(t.Normal);
            uint shaded = Tint(t.Color, lit, 1f, 1f, 1f);
            var texture = t.Texture;
            float inverse = 1f / area;
            // affine uv (orthographic): one level of detail per triangle, log2 of texels per pixel
            float lod = 0f;
            if (texture != null && texture.Levels > 1)
            {
                float uvArea = Math.Abs((t.UB - t.UA) * (t.VC - t.VA) - (t.VB - t.VA) * (t.UC - t.UA));
                float ratio = texture.TexelArea(uvArea) / Math.Abs(area);
                lod = ratio > 0f ? 0.5f * MathF.Log2(ratio) + LodBias : 0f;
            }
            for (int y = y0; y <= y1; y++)
            {
                float py = y + 0.5f;
                int row = y * view.Width;
                for (int x = x0; x <= x1; x++)
                {
                    float px = x + 0.5f;
                    float wa = ((bx - px) * (cy - py) - (by - py) * (cx - px)) * inverse;
                    float wb = ((cx - px) * (ay - py) - (cy - py) * (ax - px)) * inverse;
                    float wc = 1f - wa - wb;
                    if (wa < 0f || wb < 0f || wc < 0f) continue;
                    float z = wa * az + wb * bz + wc * cz;
                    int i = row + x;
                    if (z >= depth[i]) continue;
                    depth[i] = z;
                    if (texture == null) Color[i] = shaded;
                    else
                    {
                        float sa = wa, sb = wb, sc = wc;
                        if (ShadingRate > 1)
                        {
                            // the texture is read at the centre of the final pixel (barycentrics extrapolated there if need be)
                            float qx = (x / ShadingRate) * ShadingRate + 0.5f * ShadingRate, qy = (y / ShadingRate) * ShadingRate + 0.5f * ShadingRate;
                            sa = ((bx - qx) * (cy - qy) - (by - qy) * (cx - qx)) * inverse;
                            sb = ((cx - qx) * (ay - qy) - (cy - qy) * (ax - qx)) * inverse;
                            sc = 1f - sa - sb;
                        }
                        var (tr, tg, tb) = texture.Sample(sa * t.UA + sb * t.UB + sc * t.UC, sa * t.VA + sb * t.VB + sc * t.VC, lod);
                        Color[i] = Tint(t.Color, lit, tr, tg, tb);
                    }
                    Kind[i] = t.Kind;
                }
            }
        }

        /// <summary>
        /// Area in pixels² of the front faces of <paramref name="kind"/> projected onto the screen: for a closed surface
        /// whose projection does not overlap itself, the area of its silhouette (what the pixels should cover when nothing
        /// is in front of it). Facing is decided by the geometric normal oriented like the triangle's normal.
        /// </summary>
        public static double ProjectedFrontArea(IReadOnlyList<SceneTriangle> triangles, OrthographicView view, SurfaceKind kind)
        {
            double sum = 0;
            foreach (var t in triangles)
            {
                if (t.Kind != kind) continue;
                var geometric = Float3.Cross(t.B - t.A, t.C - t.A);
                if (Float3.Dot(geometric, t.Normal) < 0f) geometric = -geometric;
                if (Float3.Dot(geometric, view.TowardCamera) <= 0f) continue;
                var (ax, ay, _) = view.Project(t.A);
                var (bx, by, _) = view.Project(t.B);
                var (cx, cy, _) = view.Project(t.C);
                sum += Math.Abs((double)(bx - ax) * (cy - ay) - (double)(by - ay) * (cx - ax)) / 2;
            }
            return sum;
        }
    }
}
