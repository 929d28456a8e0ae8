using System;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// An orthographic camera for the figures: looks at <see cref="Target"/> from the direction given by a yaw about
    /// +Y and a pitch above the horizon, at a fixed scale in pixels per metre. Screen x grows to the right, y downwards.
    /// </summary>
    public sealed class OrthographicView
    {
        /// <summary>World point at the image centre (m).</summary>
        public Float3 Target { get; }
        /// <summary>Image width in pixels.</summary>
        public int Width { get; }
        /// <summary>Image height in pixels.</summary>
        public int Height { get; }
        /// <summary>Scale in pixels per metre.</summary>
        public float PixelsPerMetre { get; }
        /// <summary>Unit vector from the scene towards the camera.</summary>
        public Float3 TowardCamera { get; }
        /// <summary>Unit vector of screen-right in the world.</summary>
        public Float3 Right { get; }
        /// <summary>Unit vector of screen-up in the world.</summary>
        public Float3 Up { get; }

        /// <summary>A view; <paramref name="yawDegrees"/> 0 looks along +Z (from −Z), positive turns the camera towards −X.</summary>
        public OrthographicView(Float3 target, float yawDegrees, float pitchDegrees, float pixelsPerMetre, int width, int height)
        {
            if (!(pixelsPerMetre > 0f)) throw new ArgumentOutOfRangeException(nameof(pixelsPerMetre), pixelsPerMetre, "pixelsPerMetre must be > 0");
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), "the image needs at least one pixel");
            Target = target;
            Width = width;
            Height = height;
            PixelsPerMetre = pixelsPerMetre;
            double yaw = yawDegrees * Math.PI / 180, pitch = pitchDegrees * Math.PI / 180;
            TowardCamera = new Float3((float)(-Math.Sin(yaw) * Math.Cos(pitch)), (float)Math.Sin(pitch), (float)(-Math.Cos(yaw) * Math.Cos(pitch)));
            // Unity's left-handed frame: looking along +Z with +Y up, screen-right is +X
            Right = Float3.Cross(TowardCamera, new Float3(0f, 1f, 0f)).NormalizedOr(new Float3(1f, 0f, 0f));
            Up = Float3.Cross(Right, TowardCamera);
        }

        /// <summary>The same view at <paramref name="factor"/> times the resolution (supersampling).</summary>
        public OrthographicView Scaled(int factor) => new OrthographicView(Target, TowardCamera, Right, Up, PixelsPerMetre * factor, Width * factor, Height * factor);

        OrthographicView(Float3 target, Float3 toward, Float3 right, Float3 up, float scale, int width, int height)
        {
            Target = target;
            TowardCamera = toward;
            Right = right;
            Up = up;
            PixelsPerMetre = scale;
            Width = width;
            Height = height;
        }

        /// <summary>Screen position of a world point: x, y in pixels and the depth (m, larger = farther from the camera).</summary>
        public (float X, float Y, float Depth) Project(Float3 world)
        {
            var d = world - Target;
            return (Width * 0.5f + Float3.Dot(d, Right) * PixelsPerMetre,
                    Height * 0.5f - Float3.Dot(d, Up) * PixelsPerMetre,
                    -Float3.Dot(d, TowardCamera));
        }
    }
}
