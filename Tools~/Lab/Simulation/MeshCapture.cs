using HookeRope.Geometry;
using HookeRope.Lab.Scenarios;

namespace HookeRope.Lab.Simulation
{
    /// <summary>Captures the tube mesh of a rope through the core's RopeSimulation facade (broken ends included).</summary>
    public static class MeshCapture
    {
        /// <summary>The tube mesh at time t in world metres.</summary>
        public static MeshSnapshot Capture(RopeSetup setup, Scenario s, double t)
        {
            var sim = setup.Simulation;
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            var update = sim.FillMesh(vertices, indices);
            var origin = setup.Rope.Origin;  // the vertices are in the rope-local frame
            var snapshot = new MeshSnapshot { Time = t, Vertices = new float[update.VertexCount * 12], Indices = new int[update.IndexCount], TubeIndexCount = update.TubeIndexCount };
            for (int i = 0; i < update.VertexCount; i++)
            {
                var v = vertices[i];
                int o = 12 * i;
                snapshot.Vertices[o] = v.PX + origin.X;
                snapshot.Vertices[o + 1] = v.PY + origin.Y;
                snapshot.Vertices[o + 2] = v.PZ + origin.Z;
                snapshot.Vertices[o + 3] = v.NX;
                snapshot.Vertices[o + 4] = v.NY;
                snapshot.Vertices[o + 5] = v.NZ;
                snapshot.Vertices[o + 6] = v.TX;
                snapshot.Vertices[o + 7] = v.TY;
                snapshot.Vertices[o + 8] = v.TZ;
                snapshot.Vertices[o + 9] = v.TW;
                snapshot.Vertices[o + 10] = v.U;
                snapshot.Vertices[o + 11] = v.V;
            }
            System.Array.Copy(indices, snapshot.Indices, update.IndexCount);
            return snapshot;
        }
    }
}
