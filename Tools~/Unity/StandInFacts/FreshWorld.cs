using System;

namespace HookeRope.StandIn.Facts
{
    /// <summary>A facts test's own stand-in world: reset when made and when disposed, the play-mode flag restored.</summary>
    internal sealed class FreshWorld : IDisposable
    {
        private readonly bool wasPlaying;

        public FreshWorld()
        {
            wasPlaying = World.IsPlaying;
            World.Reset();
        }

        public void Dispose()
        {
            World.Reset();
            World.IsPlaying = wasPlaying;
        }
    }
}
