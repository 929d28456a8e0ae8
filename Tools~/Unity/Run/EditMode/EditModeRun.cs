using HookeRope.StandIn;

// This assembly plays Unity's Edit Mode test platform.
[assembly: StandInTestRun(StandInPlatform.EditMode)]
