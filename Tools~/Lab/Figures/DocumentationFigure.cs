using System.Collections.Generic;

namespace HookeRope.Lab.Figures
{
    /// <summary>One figure of the manual: the scene, the camera, the annotations and the file name it is written under.</summary>
    public sealed class DocumentationFigure
    {
        /// <summary>File name (PNG) inside the output folder.</summary>
        public string FileName;
        /// <summary>The triangles (rope mesh from the core, rig props).</summary>
        public FigureScene Scene = new FigureScene();
        /// <summary>The camera at the final resolution.</summary>
        public OrthographicView View;
        /// <summary>Labels, arrows and captions drawn over the render.</summary>
        public List<FigureAnnotation> Annotations = new List<FigureAnnotation>();
        /// <summary>Optional zoomed detail drawn into the figure (same scene, its own camera), or null.</summary>
        public FigureInset Inset;
        /// <summary>Further panels drawn into the figure, each with its own scene and camera (multi-panel figures).</summary>
        public List<FigureInset> Panels = new List<FigureInset>();
        /// <summary>The figure's caption (also drawn in the image by the paper figures), or null.</summary>
        public string Caption;
        /// <summary>Measured numbers the annotations quote (name → value), for the console summary and the tests.</summary>
        public Dictionary<string, double> Numbers = new Dictionary<string, double>();
    }

    /// <summary>A zoomed detail of the same scene (or a panel with its own scene) placed on the figure.</summary>
    public sealed class FigureInset
    {
        /// <summary>The detail's camera (its own size and scale).</summary>
        public OrthographicView View;
        /// <summary>Top-left corner on the figure (px).</summary>
        public SkiaSharp.SKPoint Position;
        /// <summary>Caption drawn under the detail's frame.</summary>
        public string Caption;
        /// <summary>The detail's own triangles (a panel of a multi-panel figure), or null for the figure's scene.</summary>
        public FigureScene Scene;
        /// <summary>Drawn at this many figure pixels per rendered pixel (nearest neighbour; 1 = as rendered).</summary>
        public int Magnify = 1;
    }

    /// <summary>What writing a figure produced.</summary>
    public sealed class FigureStats
    {
        /// <summary>Path of the PNG written.</summary>
        public string Path;
        /// <summary>Image width (px).</summary>
        public int Width;
        /// <summary>Image height (px).</summary>
        public int Height;
        /// <summary>File size (bytes).</summary>
        public long Bytes;
        /// <summary>Pixels (final resolution, fractional from the supersampling) where the rope is visible in the render.</summary>
        public double RopePixels;
        /// <summary>Pixels (final resolution) where burr strands are visible in the main render.</summary>
        public double BurrPixels;
        /// <summary>Projected area of the rope mesh's front faces (px² at the final resolution).</summary>
        public double ProjectedRopeArea;

        /// <summary><see cref="RopePixels"/> / <see cref="ProjectedRopeArea"/>: 1 when the rope is unoccluded and its projection does not overlap itself.</summary>
        public double Coverage => ProjectedRopeArea > 0 ? RopePixels / ProjectedRopeArea : 0;
    }
}
