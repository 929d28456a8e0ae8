using System.Runtime.CompilerServices;

// The friends of HookeRope.Core: the Unity runtime and editor assemblies, the Unity and headless test assemblies,
// and the bench tool. The headless stand-in runs (Tools~/Unity/Run) are added in
// Tools~/Core/HookeRope.Core.csproj: they exist only there, and package sources must not name the stand-in
// (StandInIsolationTests). Not the lab: it lives on the public API, which proves that API is enough
// (the burr texture generator is public for it: the lab's figures paint the strands with it).
[assembly: InternalsVisibleTo("HookeRope")]
[assembly: InternalsVisibleTo("HookeRope.Editor")]
[assembly: InternalsVisibleTo("HookeRope.Tests")]
[assembly: InternalsVisibleTo("HookeRope.Tests.Editor")]
[assembly: InternalsVisibleTo("HookeRope.Tests.Runtime")]
[assembly: InternalsVisibleTo("HookeRope.Bench")]
