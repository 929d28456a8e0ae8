using System;
using System.Collections.Generic;
using HookeRope.Lab.Scenarios;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Simulation
{
    /// <summary>One event as it was applied: when (s, the start of the host step it acted on) and what.</summary>
    public struct AppliedEvent
    {
        /// <summary>Simulated time at which it acted, s.</summary>
        public double Time;
        /// <summary>Description.</summary>
        public string What;
    }

    /// <summary>
    /// Plays a scenario's timed events and drives its pinned ends (keyframes, targets set by events, velocity
    /// profiles). An event at time tₑ acts on the state at the host-step boundary nearest tₑ: before the step
    /// that starts at k·Δt with k·Δt ≥ tₑ − Δt/2.
    /// </summary>
    public sealed class EventPlayer
    {
        readonly Scenario scenario;
        readonly RopeSetup setup;
        readonly List<EventSpec> events;
        int next;
        readonly EndDriver start, end;

        /// <summary>Events applied so far, in order.</summary>
        public readonly List<AppliedEvent> Applied = new List<AppliedEvent>();

        sealed class EndDriver
        {
            public int Pin = -1;
            public bool Keyframed;
            public Float3 Target;
            public Float3 Velocity;
            public double Until = double.NegativeInfinity;
        }

        /// <summary>A player for <paramref name="s"/> acting on <paramref name="setup"/>.</summary>
        public EventPlayer(Scenario s, RopeSetup setup)
        {
            scenario = s;
            this.setup = setup;
            events = s.Events;
            start = Driver(s.Start, setup.StartPin);
            end = Driver(s.End, setup.EndPin);
        }

        EndDriver Driver(AttachmentSpec a, int pin)
        {
            var d = new EndDriver { Pin = pin, Keyframed = a.Kind == AttachmentKind.Keyframes };
            if (pin >= 0) d.Target = setup.Rope.GetPinTarget(pin);
            return d;
        }

        /// <summary>Applies the events due before the step from <paramref name="t0"/> to <paramref name="t0"/> + <paramref name="dt"/> (s), then sets the pin targets for the end of that step.</summary>
        public void BeforeStep(double t0, double dt)
        {
            while (next < events.Count && events[next].Time <= t0 + dt / 2)
            {
                Apply(events[next], t0);
                next++;
            }
            Drive(start, scenario.Start, t0, dt);
            Drive(end, scenario.End, t0, dt);
        }

        void Drive(EndDriver d, AttachmentSpec a, double t0, double dt)
        {
            if (d.Pin < 0) return;
            double t1 = t0 + dt;
            if (d.Until > t0)
            {
                double moving = Math.Min(t1, d.Until) - t0;
                d.Target = d.Target + d.Velocity * (float)moving;
                setup.Rope.SetPinTarget(d.Pin, d.Target);
            }
            else if (d.Keyframed)
            {
                d.Target = a.PositionAt(t1);
                setup.Rope.SetPinTarget(d.Pin, d.Target);
            }
        }

        void Apply(EventSpec e, double t)
        {
            var rope = setup.Rope;
            var d = e.AtStart ? start : end;
            switch (e.Kind)
            {
                case EventKind.PinTarget:
                    d.Keyframed = false;
                    d.Until = double.NegativeInfinity;
                    d.Target = e.Vector;
                    rope.SetPinTarget(d.Pin, d.Target);
                    break;
                case EventKind.PinVelocity:
                    d.Keyframed = false;
                    d.Velocity = e.Vector;
                    d.Until = e.Until;
                    break;
                case EventKind.ReleasePin:
                    rope.ReleasePin(d.Pin);
                    d.Pin = -1;
                    break;
                case EventKind.Impulse:
                {
                    int i = Particle(e.At);
                    double mass = ParticleMass(scenario, i);
                    rope.SetVelocity(i, rope.GetVelocity(i) + e.Vector * (float)(1.0 / mass));
                    break;
                }
                case EventKind.Damping:
                    rope.Settings.Damping = (float)e.Value;
                    break;
                default:
                {
                    int segment = Math.Min((int)(e.At * rope.SegmentCount), rope.SegmentCount - 1);
                    if (!rope.IsSegmentBroken(segment)) rope.BreakSegment(segment);
                    break;
                }
            }
            Applied.Add(new AppliedEvent { Time = t, What = e.Describe() });
        }

        int Particle(double at) => (int)Math.Round(at * (setup.Rope.ParticleCount - 1));

        /// <summary>Mass of particle <paramref name="i"/> in kg: its share of the rope (half a segment at the ends) plus a body attached there.</summary>
        public static double ParticleMass(Scenario s, int i)
        {
            int n = s.Rope.Segments;
            double segment = s.Rope.ResolvedLinearDensity * s.Rope.RestLength / n;
            double mass = i == 0 || i == n ? segment / 2 : segment;
            if (i == 0) mass += s.Start.LoadMass;
            if (i == n) mass += s.End.LoadMass;
            return mass;
        }
    }
}
