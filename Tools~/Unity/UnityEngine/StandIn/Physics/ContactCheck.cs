using System;
using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the stand-in does not solve contacts, so after each step it checks that none exists. A
    /// non-trigger collider of a non-kinematic Rigidbody that interpenetrates another non-trigger collider (not on the
    /// same body) is a contact Unity would resolve; a trigger overlap involving a Rigidbody, where a script on either
    /// side could receive OnTrigger messages, is one Unity would report. Both throw a NotSupportedException naming the
    /// colliders, so a test can never silently diverge from Unity. Allocation-free after warm-up.
    /// </summary>
    internal static class ContactCheck
    {
        static Collider[] s_Colliders = new Collider[16];
        static Rigidbody[] s_Bodies = new Rigidbody[16];
        static WorldShape[] s_Shapes = new WorldShape[16];

        internal static void AfterStep(IReadOnlyList<Collider> colliders)
        {
            int n = Gather(colliders);
            try
            {
                for (int i = 0; i < n; i++)
                for (int j = i + 1; j < n; j++)
                    Check(i, j);
            }
            finally
            {
                Array.Clear(s_Colliders, 0, n);
                Array.Clear(s_Bodies, 0, n);
            }
        }

        internal static void Reset()
        {
            s_Colliders = new Collider[16];
            s_Bodies = new Rigidbody[16];
            s_Shapes = new WorldShape[16];
        }

        static int Gather(IReadOnlyList<Collider> colliders)
        {
            if (s_Colliders.Length < colliders.Count)
            {
                int size = Math.Max(colliders.Count, 2 * s_Colliders.Length);
                s_Colliders = new Collider[size];
                s_Bodies = new Rigidbody[size];
                s_Shapes = new WorldShape[size];
            }
            int n = 0;
            for (int i = 0; i < colliders.Count; i++)
            {
                var collider = colliders[i];
                if (!collider.InScene) continue;
                var body = collider.attachedRigidbody;
                s_Colliders[n] = collider;
                s_Bodies[n] = body is object && body.InScene ? body : null;
                s_Shapes[n] = collider.PhysicsShape(s_Bodies[n]);
                n++;
            }
            return n;
        }

        static void Check(int i, int j)
        {
            Rigidbody a = s_Bodies[i], b = s_Bodies[j];
            if (ReferenceEquals(a, b)) return;
            Collider ca = s_Colliders[i], cb = s_Colliders[j];
            bool trigger = ca.isTrigger || cb.isTrigger;
            if (trigger)
            {
                if (a is null && b is null) return;
                if (!HasScript(ca, a) && !HasScript(cb, b)) return;
            }
            else if (!(a is object && a.IsDynamic) && !(b is object && b.IsDynamic))
            {
                return;
            }
            ref readonly var sa = ref s_Shapes[i];
            ref readonly var sb = ref s_Shapes[j];
            if (sa.Kind == ShapeKind.None || sb.Kind == ShapeKind.None) return;
            if (sa.Kind == ShapeKind.Unsupported) throw StandInError.Unsupported(sa.Unsupported + " in the contact check against " + cb.Describe());
            if (sb.Kind == ShapeKind.Unsupported) throw StandInError.Unsupported(sb.Unsupported + " in the contact check against " + ca.Describe());
            if (!AabbsOverlap(sa, sb) || !ShapeOverlap.Penetrate(sa, sb)) return;
            if (trigger)
                throw new NotSupportedException("The Unity stand-in does not send trigger messages: " + ca.Describe() + " and " + cb.Describe() +
                                                " overlap after the physics step with a trigger involved (Unity would send OnTriggerEnter/Stay/Exit to their scripts). Keep triggers clear of Rigidbodies in stand-in tests.");
            throw new NotSupportedException("The Unity stand-in does not solve contacts: " + ca.Describe() + " and " + cb.Describe() +
                                            " interpenetrate after the physics step (Unity would push them apart and send OnCollision messages). Keep dynamic bodies clear of other colliders in stand-in tests.");
        }

        /// <summary>Whether a script on the collider's GameObject or its Rigidbody's could receive trigger messages.</summary>
        static bool HasScript(Collider collider, Rigidbody body) =>
            collider.GetComponent<MonoBehaviour>() is object || body is object && body.GetComponent<MonoBehaviour>() is object;

        static bool AabbsOverlap(in WorldShape a, in WorldShape b)
        {
            Vector3 ha = a.AabbHalf(), hb = b.AabbHalf(), d = b.Center - a.Center;
            return Math.Abs(d.x) <= ha.x + hb.x && Math.Abs(d.y) <= ha.y + hb.y && Math.Abs(d.z) <= ha.z + hb.z;
        }
    }
}
