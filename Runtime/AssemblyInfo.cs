using System.Runtime.CompilerServices;

// The editor builds the static-sag preview through ElasticRope.CreateDetachedSimulation (the Rebuild path).
[assembly: InternalsVisibleTo("HookeRope.Editor")]
