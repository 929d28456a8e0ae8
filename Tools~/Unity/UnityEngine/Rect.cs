namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Rect: a 2D rectangle defined by its X and Y position, width and height (GUI space: y grows
    /// downwards). Stored as xMin, yMin, width, height, with the semantics of UCR Runtime/Export/Geometry/Rect.cs: setting
    /// xMin or yMin keeps the opposite edge, setting xMax or yMax keeps the position.
    /// </summary>
    public struct Rect
    {
        float m_XMin, m_YMin, m_Width, m_Height;

        /// <summary>Creates a new rectangle.</summary>
        public Rect(float x, float y, float width, float height)
        {
            m_XMin = x;
            m_YMin = y;
            m_Width = width;
            m_Height = height;
        }

        /// <summary>The X coordinate of the rectangle.</summary>
        public float x { get => m_XMin; set => m_XMin = value; }

        /// <summary>The Y coordinate of the rectangle.</summary>
        public float y { get => m_YMin; set => m_YMin = value; }

        /// <summary>The width of the rectangle, measured from the X position.</summary>
        public float width { get => m_Width; set => m_Width = value; }

        /// <summary>The height of the rectangle, measured from the Y position.</summary>
        public float height { get => m_Height; set => m_Height = value; }

        /// <summary>The minimum X coordinate of the rectangle.</summary>
        public float xMin { get => m_XMin; set { float oldMax = xMax; m_XMin = value; m_Width = oldMax - m_XMin; } }

        /// <summary>The minimum Y coordinate of the rectangle.</summary>
        public float yMin { get => m_YMin; set { float oldMax = yMax; m_YMin = value; m_Height = oldMax - m_YMin; } }

        /// <summary>The maximum X coordinate of the rectangle.</summary>
        public float xMax { get => m_Width + m_XMin; set => m_Width = value - m_XMin; }

        /// <summary>The maximum Y coordinate of the rectangle.</summary>
        public float yMax { get => m_Height + m_YMin; set => m_Height = value - m_YMin; }
    }
}
