using System;
using System.Globalization;
using System.Runtime.InteropServices;
using HookeRope.Geometry;
using HookeRope.Bench;
using HookeRope.World;

namespace HookeRope.Kernels
{
    /// <summary>
    /// Issue 18's goal world in the probe: <c>goal-world:N</c> is N lanyards × 64 segments with 16-sided tube meshes in one
    /// <see cref="RopeWorld"/> on 1 worker (Tools~/Bench/GoalScene.cs, the scene the bench's goal rows time), warmed up
    /// by <see cref="GoalScene.WarmUpFrames"/> frames; <c>run goal-world:N K</c> then steps and fills K frames of the
    /// bench's window. <c>goal-step:N</c> is the same world stepped without mesh fills in those K frames (the meshes of
    /// the warm-up are filled as in the bench, and the fills never change the physics), so the difference of the two
    /// counts is the mesh's. goal-count.sh counts K = 0 against K = <see cref="GoalScene.WindowFrames"/> under callgrind.
    /// <c>goal-lean:N</c> is <c>goal-world:N</c> with its meshes filled without tangents (<see cref="RopeMeshSlot.Tangents"/>
    /// off: 32-byte vertices, the same positions, normals and uv).
    /// </summary>
    internal static class GoalWorldScene
    {
        /// <summary>Segments per lanyard (the goal's).</summary>
        public const int Segments = 64;

        /// <summary>True for <c>goal-world:N</c>, <c>goal-lean:N</c> and <c>goal-step:N</c>.</summary>
        public static bool Is(string name) =>
            name.StartsWith("goal-world:", StringComparison.Ordinal) || name.StartsWith("goal-lean:", StringComparison.Ordinal)
            || name.StartsWith("goal-step:", StringComparison.Ordinal);

        /// <summary>
        /// Builds the scene, steps <paramref name="frames"/> frames of the window and prints the state hash of every rope
        /// (folded), the work units (ropes × segments × substeps × frames) and the tube vertices the frames filled.
        /// </summary>
        public static int Run(string name, int frames)
        {
            bool lean = name.StartsWith("goal-lean:", StringComparison.Ordinal);
            bool mesh = lean || name.StartsWith("goal-world:", StringComparison.Ordinal);
            int ropes = int.Parse(name.Substring(name.IndexOf(':') + 1), CultureInfo.InvariantCulture);
            if (ropes < 1) throw new ArgumentOutOfRangeException(nameof(name), ropes, "the rope count N of " + name + " must be at least 1.");
            long vertices = 0;
            ulong hash = 14695981039346656037UL;
            using (var world = GoalScene.Build(ropes, Segments, 1, warmUpFrames: GoalScene.WarmUpFrames, tangents: !lean))
            {
                for (int f = 0; f < frames; f++)
                {
                    if (mesh)
                    {
                        world.StepAndFillMeshes(GoalScene.Frame);
                        for (int i = 0; i < world.Count; i++) vertices += world.GetMeshSlot(i).Update.VertexCount;
                    }
                    else world.Step(GoalScene.Frame);
                }
                for (int i = 0; i < world.Count; i++) hash = (hash ^ Program.Hash(world.GetRope(i).Rope)) * 1099511628211UL;
            }
            long units = (long)ropes * Segments * GoalScene.Substeps * frames;
            int first = GoalScene.WarmUpFrames + 1;
            Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0} frames {1}-{2}: {3:x16} units {4} vertices {5}",
                name, first, first + frames - 1, hash, units, vertices));
            return 0;
        }

        /// <summary>
        /// Builds the goal world of <paramref name="ropes"/> lanyards, steps and fills <paramref name="frames"/> frames of the
        /// window and prints an FNV-1a hash of every filled vertex's and index's bits, every frame (a mesh change that is meant
        /// to be bit-identical keeps it), with the vertex count.
        /// </summary>
        public static int MeshHash(int ropes, int frames)
        {
            if (ropes < 1) throw new ArgumentOutOfRangeException(nameof(ropes), ropes, "the rope count of mesh-hash must be at least 1.");
            if (frames < 1) throw new ArgumentOutOfRangeException(nameof(frames), frames, "the frame count of mesh-hash must be at least 1.");
            ulong hash = 14695981039346656037UL;
            long vertices = 0;
            using (var world = GoalScene.Build(ropes, Segments, 1, warmUpFrames: GoalScene.WarmUpFrames))
            {
                for (int f = 0; f < frames; f++)
                {
                    world.StepAndFillMeshes(GoalScene.Frame);
                    for (int i = 0; i < world.Count; i++)
                    {
                        RopeMeshSlot slot = world.GetMeshSlot(i);
                        ReadOnlySpan<byte> bytes = MemoryMarshal.AsBytes(new ReadOnlySpan<TubeVertex>(slot.Vertices, 0, slot.Update.VertexCount));
                        for (int b = 0; b < bytes.Length; b++) hash = (hash ^ bytes[b]) * 1099511628211UL;
                        ReadOnlySpan<byte> indices = MemoryMarshal.AsBytes(new ReadOnlySpan<int>(slot.Indices, 0, slot.Update.IndexCount));
                        for (int b = 0; b < indices.Length; b++) hash = (hash ^ indices[b]) * 1099511628211UL;
                        vertices += slot.Update.VertexCount;
                    }
                }
            }
            Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "mesh-hash goal-world:{0} frames {1}-{2}: {3:x16} vertices {4}",
                ropes, GoalScene.WarmUpFrames + 1, GoalScene.WarmUpFrames + frames, hash, vertices));
            return 0;
        }
    }
}
