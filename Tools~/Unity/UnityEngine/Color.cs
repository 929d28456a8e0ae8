namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Color: RGBA colour, components 0 to 1.</summary>
    public struct Color
    {
        /// <summary>Red component of the color.</summary>
        public float r;
        /// <summary>Green component of the color.</summary>
        public float g;
        /// <summary>Blue component of the color.</summary>
        public float b;
        /// <summary>Alpha component of the color (0 is transparent, 1 is opaque).</summary>
        public float a;

        /// <summary>Constructs a new Color with given r,g,b,a components.</summary>
        public Color(float r, float g, float b, float a) { this.r = r; this.g = g; this.b = b; this.a = a; }

        /// <summary>Constructs a new Color with given r,g,b components and sets a to 1.</summary>
        public Color(float r, float g, float b) { this.r = r; this.g = g; this.b = b; a = 1f; }

        /// <summary>Linearly interpolates between colors a and b by t.</summary>
        public static Color Lerp(Color a, Color b, float t) => throw Shim.NotRun;

        /// <summary>Solid white. RGBA is (1, 1, 1, 1).</summary>
        public static Color white => throw Shim.NotRun;

        /// <summary>Solid red. RGBA is (1, 0, 0, 1).</summary>
        public static Color red => throw Shim.NotRun;

        /// <summary>Solid green. RGBA is (0, 1, 0, 1).</summary>
        public static Color green => throw Shim.NotRun;

        /// <summary>Solid yellow. RGBA is (1, 0.92, 0.016, 1).</summary>
        public static Color yellow => throw Shim.NotRun;

        /// <summary>Cyan. RGBA is (0, 1, 1, 1).</summary>
        public static Color cyan => throw Shim.NotRun;
    }
}
