using System.Runtime.CompilerServices;

// The editor builds the static-sag preview through ElasticRope.CreateDetachedSimulation (the Rebuild path).
[assembly: InternalsVisibleTo("HookeRope.Editor")]

// The edit-mode component tests play player builds without a shader through RopeDefaultMaterial's internal seam.
[assembly: InternalsVisibleTo("HookeRope.Tests.Editor")]

// The play-mode tests check that the shared multi-rope world's threads are gone (RopeWorldScheduler.World).
[assembly: InternalsVisibleTo("HookeRope.Tests.Runtime")]
