namespace HookeRope.Solver
{
    /// <summary>An axis-aligned box of particle positions (rope-local m, lowest and highest corner) and their largest radius (m).</summary>
    internal readonly struct ParticleBox
    {
        public readonly float LowX, LowY, LowZ, HighX, HighY, HighZ, Radius;

        public ParticleBox(float lowX, float lowY, float lowZ, float highX, float highY, float highZ, float radius)
        {
            LowX = lowX; LowY = lowY; LowZ = lowZ;
            HighX = highX; HighY = highY; HighZ = highZ;
            Radius = radius;
        }

        /// <summary>The smallest box holding boxes a and b, with the larger radius (a NaN corner of b is left out).</summary>
        public static ParticleBox Union(in ParticleBox a, in ParticleBox b) => new ParticleBox(
            b.LowX < a.LowX ? b.LowX : a.LowX, b.LowY < a.LowY ? b.LowY : a.LowY, b.LowZ < a.LowZ ? b.LowZ : a.LowZ,
            b.HighX > a.HighX ? b.HighX : a.HighX, b.HighY > a.HighY ? b.HighY : a.HighY, b.HighZ > a.HighZ ? b.HighZ : a.HighZ,
            b.Radius > a.Radius ? b.Radius : a.Radius);

        /// <summary>The box of the single point (x, y, z) of radius r.</summary>
        public static ParticleBox Point(float x, float y, float z, float r) => new ParticleBox(x, y, z, x, y, z, r);
    }
}
