using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Diagnosers;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Running;
using BenchmarkDotNet.Toolchains.InProcess.Emit;

namespace HookeRope.Bench
{
    /// <summary>
    /// Entry point: <c>goal …</c> and <c>frames …</c> run <see cref="GoalCommand"/> (issue 18's table of many ropes),
    /// <c>mesh …</c> and <c>meshframes …</c> run <see cref="MeshBench"/> (the tube mesh alone), <c>collisions …</c> and
    /// <c>collide …</c> <see cref="CollisionCommand"/> (the collision broad phase);
    /// anything else runs BenchmarkDotNet with a short in-process job so the whole suite runs in a few minutes.
    /// </summary>
    public static class Program
    {
        public static int Main(string[] args)
        {
            if (args.Length > 0 && args[0] == "goal") return GoalCommand.Execute(args);
            if (args.Length == 5 && args[0] == "frames") return GoalCommand.Frames(args);
            if (args.Length > 0 && args[0] == "mesh") return MeshBench.Execute(args);
            if (args.Length >= 6 && args[0] == "meshframes") return MeshBench.Frames(args);
            if (args.Length > 0 && args[0] == "collisions") return CollisionCommand.Execute(args);
            if (args.Length >= 3 && args[0] == "collide") return CollisionCommand.Collide(args);
            var job = Job.Default
                .WithToolchain(InProcessEmitToolchain.Instance)
                .WithWarmupCount(2)
                .WithIterationCount(5)
                .WithLaunchCount(1)
                .WithId("Short");
            var config = DefaultConfig.Instance
                .AddJob(job)
                .AddDiagnoser(MemoryDiagnoser.Default)
                .AddColumn(new PerUnitColumn())
                .WithOptions(ConfigOptions.DisableOptimizationsValidator)
                .WithArtifactsPath(System.IO.Path.Combine(System.IO.Path.GetTempPath(), "HookeRope.Bench"));
            BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args, config);
            return 0;
        }
    }
}
