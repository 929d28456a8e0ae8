using System.Runtime.CompilerServices;

// The harness attribute that sets up a stand-in test run is internal: only the stand-in test assemblies use it.
[assembly: InternalsVisibleTo("HookeRope.StandIn.EditMode")]
[assembly: InternalsVisibleTo("HookeRope.StandIn.PlayMode")]
