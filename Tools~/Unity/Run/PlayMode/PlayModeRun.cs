using HookeRope.StandIn;

// This assembly plays Unity's Play Mode test platform.
[assembly: StandInTestRun(StandInPlatform.PlayMode)]
