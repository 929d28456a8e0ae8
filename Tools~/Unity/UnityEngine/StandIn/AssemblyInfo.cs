using System.Runtime.CompilerServices;

// The stand-in's control surface (scene reset, player loop, log capture) is internal: only the other stand-in
// assemblies and the headless test runs may drive it. Package code sees exactly Unity's public API.
[assembly: InternalsVisibleTo("UnityEditor")]
[assembly: InternalsVisibleTo("UnityEngine.TestRunner")]
[assembly: InternalsVisibleTo("HookeRope.StandIn.EditMode")]
[assembly: InternalsVisibleTo("HookeRope.StandIn.PlayMode")]
