using System.Runtime.CompilerServices;

// The edit-mode tests reach the editor helpers (menu, tension colour map). The headless stand-in run is added in
// Tools~/Unity/Check/Editor/HookeRope.Editor.csproj: package sources must not name the stand-in.
[assembly: InternalsVisibleTo("HookeRope.Tests.Editor")]
