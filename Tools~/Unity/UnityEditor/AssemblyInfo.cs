using System.Runtime.CompilerServices;

// The stand-in's editor internals (undo log, loaded prefab assets) are visible to the stand-in test runs only.
[assembly: InternalsVisibleTo("HookeRope.StandIn.EditMode")]
[assembly: InternalsVisibleTo("HookeRope.StandIn.PlayMode")]
