using HookeRope.Mathematics;
using SkiaSharp;

namespace HookeRope.Lab.Figures
{
    /// <summary>Something drawn over a rendered figure (SkiaSharp, final resolution): a label, an arrow, a dashed guide.</summary>
    public abstract class FigureAnnotation
    {
        /// <summary>Ink of labels and leaders.</summary>
        public static readonly SKColor Ink = new SKColor(30, 34, 40);

        /// <summary>Draws the annotation onto <paramref name="canvas"/> through <paramref name="view"/>.</summary>
        public abstract void Draw(SKCanvas canvas, OrthographicView view, SKFont font);

        /// <summary>Screen point of a world point.</summary>
        protected static SKPoint At(OrthographicView view, Float3 world)
        {
            var (x, y, _) = view.Project(world);
            return new SKPoint(x, y);
        }

        /// <summary>A stroke paint.</summary>
        protected static SKPaint Stroke(SKColor color, float width, bool dashed = false) => new SKPaint
        {
            Color = color, IsAntialias = true, Style = SKPaintStyle.Stroke, StrokeWidth = width,
            PathEffect = dashed ? SKPathEffect.CreateDash(new[] { 7f, 5f }, 0f) : null,
        };

        /// <summary>Draws text lines in a white box whose top-left corner is <paramref name="topLeft"/>; returns the box.</summary>
        protected static SKRect TextBox(SKCanvas canvas, SKFont font, SKPoint topLeft, string text, SKColor color)
        {
            var lines = text.Split('\n');
            float width = 0;
            foreach (var line in lines) width = System.Math.Max(width, font.MeasureText(line));
            float lineHeight = font.Size * 1.25f;
            var box = new SKRect(topLeft.X, topLeft.Y, topLeft.X + width + 12, topLeft.Y + lines.Length * lineHeight + 8);
            using (var fill = new SKPaint { Color = new SKColor(255, 255, 255, 235), IsAntialias = true })
                canvas.DrawRoundRect(box, 4, 4, fill);
            using (var border = Stroke(new SKColor(150, 156, 165), 1f))
                canvas.DrawRoundRect(box, 4, 4, border);
            using (var ink = new SKPaint { Color = color, IsAntialias = true })
            {
                for (int i = 0; i < lines.Length; i++)
                    canvas.DrawText(lines[i], box.Left + 6, box.Top + 4 + font.Size + i * lineHeight, SKTextAlign.Left, font, ink);
            }
            return box;
        }
    }

    /// <summary>A text box (lines split at '\n') placed <see cref="Offset"/> pixels from a world point, with a leader line and a dot.</summary>
    public sealed class FigureLabel : FigureAnnotation
    {
        /// <summary>The world point the label names (m).</summary>
        public Float3 Point;
        /// <summary>Top-left of the text box relative to the point's screen position (px).</summary>
        public SKPoint Offset;
        /// <summary>The text.</summary>
        public string Text;
        /// <summary>Text colour.</summary>
        public SKColor Color = Ink;

        /// <inheritdoc />
        public override void Draw(SKCanvas canvas, OrthographicView view, SKFont font)
        {
            var p = At(view, Point);
            var lines = Text.Split('\n');
            float height = lines.Length * font.Size * 1.25f + 8;
            float width = 0;
            foreach (var line in lines) width = System.Math.Max(width, font.MeasureText(line));
            var topLeft = p + Offset;
            var attach = new SKPoint(Offset.X >= 0 ? topLeft.X : topLeft.X + width + 12, topLeft.Y + height / 2);
            using (var leader = Stroke(Ink, 1.2f)) canvas.DrawLine(p, attach, leader);
            using (var dot = new SKPaint { Color = Ink, IsAntialias = true }) canvas.DrawCircle(p, 3f, dot);
            TextBox(canvas, font, topLeft, Text, Color);
        }
    }

    /// <summary>An arrow between two world points, optionally dashed, with an optional text box at its tail.</summary>
    public sealed class FigureArrow : FigureAnnotation
    {
        /// <summary>Tail (m).</summary>
        public Float3 From;
        /// <summary>Head (m).</summary>
        public Float3 To;
        /// <summary>Colour.</summary>
        public SKColor Color = Ink;
        /// <summary>Line width (px).</summary>
        public float Width = 2f;
        /// <summary>Dashed line.</summary>
        public bool Dashed;
        /// <summary>Draw a head at <see cref="To"/>.</summary>
        public bool Head = true;
        /// <summary>Optional text next to the tail.</summary>
        public string Text;
        /// <summary>Text box top-left relative to the tail (px).</summary>
        public SKPoint TextOffset = new SKPoint(8, -10);

        /// <inheritdoc />
        public override void Draw(SKCanvas canvas, OrthographicView view, SKFont font)
        {
            var a = At(view, From);
            var b = At(view, To);
            using (var line = Stroke(Color, Width, Dashed)) canvas.DrawLine(a, b, line);
            var d = b - a;
            float length = d.Length;
            if (Head && length > 1f)
            {
                var u = new SKPoint(d.X / length, d.Y / length);
                var n = new SKPoint(-u.Y, u.X);
                float size = 6f + 2.5f * Width;
                using (var path = new SKPath())
                {
                    path.MoveTo(b);
                    path.LineTo(b.X - u.X * size + n.X * size * 0.45f, b.Y - u.Y * size + n.Y * size * 0.45f);
                    path.LineTo(b.X - u.X * size - n.X * size * 0.45f, b.Y - u.Y * size - n.Y * size * 0.45f);
                    path.Close();
                    using (var fill = new SKPaint { Color = Color, IsAntialias = true }) canvas.DrawPath(path, fill);
                }
            }
            if (!string.IsNullOrEmpty(Text)) TextBox(canvas, font, a + TextOffset, Text, Color);
        }
    }

    /// <summary>A caption at a fixed screen position (px from the top-left), e.g. the panel title.</summary>
    public sealed class FigureCaption : FigureAnnotation
    {
        /// <summary>Top-left of the text box (px).</summary>
        public SKPoint Position = new SKPoint(12, 12);
        /// <summary>The text (lines split at '\n').</summary>
        public string Text;

        /// <inheritdoc />
        public override void Draw(SKCanvas canvas, OrthographicView view, SKFont font) => TextBox(canvas, font, Position, Text, Ink);
    }
}
