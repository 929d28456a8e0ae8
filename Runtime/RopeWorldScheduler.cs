using System;
using System.Collections.Generic;
using HookeRope.World;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// Runs the ropes of <see cref="ElasticRopeWorld"/> (issue 18 item 4). Every ElasticRope enabled in Play is enrolled
    /// (in OnEnable order; its index in the list is its index in the <see cref="RopeWorld"/>). While two or more are
    /// enrolled, the first rope whose FixedUpdate (or Update, in Update mode) runs in a physics step runs the pass for
    /// all of them: copy-in on the main thread (<see cref="ElasticRope.BeginStep"/>), one <see cref="RopeWorld.Step"/>,
    /// copy-out on the main thread (<see cref="ElasticRope.EndStep"/>); the others find themselves stepped and return.
    /// A physics step is named by a key (Time.fixedTimeAsDouble, or −1 − Time.frameCount in Update mode), so a rope
    /// never steps twice in one and a rope enabled after the pass steps alone in it. Likewise the first enrolled
    /// rope's <see cref="RopeMeshRenderer"/> to run LateUpdate in a frame draws all of them: interpolation on the main
    /// thread into each renderer's own arrays, one <see cref="RopeWorld.FillMeshes"/>, the uploads on the main thread.
    /// Ropes enrolled during a pass join after it; a rope withdrawn (disabled, destroyed) during one is left out of the
    /// rest of it. An exception of one rope is logged with that rope as context; the others finish the pass.
    /// Allocation-free per pass once the lists have grown. Main thread only.
    /// </summary>
    internal static class RopeWorldScheduler
    {
        static readonly List<ElasticRope> s_Ropes = new List<ElasticRope>();
        static readonly List<ElasticRope> s_Joining = new List<ElasticRope>();
        static ElasticRope[] s_Pass = new ElasticRope[4];
        static RopeSimulation[] s_Stepped = new RopeSimulation[4];
        static RopeMeshRenderer[] s_Drawn = new RopeMeshRenderer[4];
        static RopeMeshSlot[] s_DrawnSlots = new RopeMeshSlot[4];
        static RopeWorld s_World;
        static int s_WorkerCount;
        static double s_StepKey = double.NaN;
        static int s_DrawFrame = -1;
        static bool s_InPass, s_QuitHooked;

        /// <summary>The world, or null while fewer than two ropes were enrolled since the last rope went.</summary>
        internal static RopeWorld World => s_World;

        /// <summary>Ropes enrolled.</summary>
        internal static int Count => s_Ropes.Count;

        /// <summary>True while two or more ropes are enrolled: the world steps them.</summary>
        internal static bool IsActive => s_Ropes.Count >= 2 && s_World != null;

        /// <summary>Threads per pass (see <see cref="ElasticRopeWorld.WorkerCount"/>; the caller checks the range).</summary>
        internal static int WorkerCount
        {
            get => s_WorkerCount > 0 ? s_WorkerCount : ElasticRopeWorld.DefaultWorkerCount;
            set => s_WorkerCount = value;
        }

        // ---- Enrolment --------------------------------------------------------------------------------------------
        /// <summary>Enrolls a built rope (no-op when it is enrolled or not built yet); during a pass it joins after it. Creates the world at the second rope.</summary>
        internal static void Enroll(ElasticRope rope)
        {
            if (rope.WorldIndex >= 0 || rope.Simulation == null) return;
            if (s_InPass)
            {
                if (IndexOf(s_Joining, rope) < 0) s_Joining.Add(rope);
                return;
            }
            rope.WorldIndex = s_Ropes.Count;
            s_Ropes.Add(rope);
            if (s_World != null) s_World.Add(rope.Simulation);
            else if (s_Ropes.Count >= 2) CreateWorld();
        }

        /// <summary>Withdraws a rope (disabled or destroyed); the ropes after it move down one index. Disposes the world when the last rope goes.</summary>
        internal static void Withdraw(ElasticRope rope)
        {
            int joining = IndexOf(s_Joining, rope);
            if (joining >= 0) s_Joining.RemoveAt(joining);
            int index = rope.WorldIndex;
            if (index < 0) return;
            rope.WorldIndex = -1;
            s_Ropes.RemoveAt(index);
            for (int i = index; i < s_Ropes.Count; i++) s_Ropes[i].WorldIndex = i;
            if (s_World != null) s_World.Remove(s_World.GetRope(index));
            if (s_Ropes.Count == 0) DisposeWorld();
        }

        /// <summary>After <see cref="ElasticRope.Rebuild"/>: an enrolled rope's new simulation takes its place in the world; a rope enabled in Play before it was built is enrolled now.</summary>
        internal static void Built(ElasticRope rope)
        {
            if (rope.WorldIndex >= 0) s_World?.Replace(rope.WorldIndex, rope.Simulation);
            else if (rope.WantsWorld) Enroll(rope);
        }

        /// <summary>Stops the world's threads and forgets every rope (Application.quitting, before a domain reload).</summary>
        internal static void Shutdown()
        {
            for (int i = 0; i < s_Ropes.Count; i++) s_Ropes[i].WorldIndex = -1;
            s_Ropes.Clear();
            s_Joining.Clear();
            DisposeWorld();
        }

        // ---- Stepping ---------------------------------------------------------------------------------------------
        /// <summary>
        /// A rope's FixedUpdate (Update in Update mode) for the physics step named <paramref name="key"/>: nothing when
        /// the rope already stepped in it; alone (<see cref="ElasticRope.Simulate"/>) when it is not in an active world,
        /// the step's pass already ran without it, or the step is longer than the world takes (an Update-mode frame
        /// over 1 s); else the pass for every enrolled rope.
        /// </summary>
        internal static void OnPhysicsStep(ElasticRope rope, float deltaTime, double key)
        {
            if (rope.SteppedKey == key) return;
            rope.SteppedKey = key;
            if (rope.WorldIndex < 0 || !IsActive || s_StepKey == key || s_InPass || !(deltaTime <= 1f))
            {
                rope.Simulate(deltaTime);
                return;
            }
            s_StepKey = key;
            Step(deltaTime, key);
        }

        /// <summary>One step of <paramref name="deltaTime"/> s of every enrolled rope on the world (copy-in, parallel step, copy-out); <paramref name="key"/> marks them stepped.</summary>
        internal static void Step(float deltaTime, double key)
        {
            if (!IsActive) return;
            if (!(deltaTime > 0f) || deltaTime > 1f)
                throw new ArgumentOutOfRangeException(nameof(deltaTime), deltaTime, "deltaTime must be in (0, 1] s for the world");
            MatchWorkerCount();
            int n = BeginPass();
            try
            {
                for (int k = 0; k < n; k++) CopyIn(k, deltaTime, key);
                InvalidOperationException failure = null;
                if (s_World != null && s_World.Count > 0)
                {
                    try
                    {
                        s_World.Step(deltaTime);
                    }
                    catch (InvalidOperationException e)
                    {
                        failure = e;
                    }
                }
                ElasticRope failed = null;
                for (int k = 0; k < n; k++)
                {
                    var rope = s_Pass[k];
                    if (!StillInPass(rope, s_Stepped[k])) continue;
                    if (s_World.LastPassFailed(rope.WorldIndex))
                    {
                        failed ??= rope;
                        continue;
                    }
                    try
                    {
                        rope.EndStep(deltaTime, s_World.GetLastStepMilliseconds(rope.WorldIndex));
                    }
                    catch (Exception e)
                    {
                        Debug.LogException(e, rope);
                    }
                }
                if (failure != null) Debug.LogException(failure, failed);
            }
            finally
            {
                EndPass(n);
            }
        }

        /// <summary>Copy-in of the pass's rope <paramref name="k"/>; a rope whose copy-in throws sits this pass out (it rejoins after it).</summary>
        static void CopyIn(int k, float deltaTime, double key)
        {
            var rope = s_Pass[k];
            s_Stepped[k] = null;
            if (rope.WorldIndex < 0) return;
            rope.SteppedKey = key;
            try
            {
                rope.BeginStep(deltaTime);
                s_Stepped[k] = rope.Simulation;
            }
            catch (Exception e)
            {
                Debug.LogException(e, rope);
                Withdraw(rope);
                s_Joining.Add(rope);
            }
        }

        /// <summary>True when the pass's rope is still enrolled with the simulation it stepped (not withdrawn or rebuilt meanwhile).</summary>
        static bool StillInPass(ElasticRope rope, RopeSimulation stepped) =>
            stepped != null && rope.WorldIndex >= 0 && s_World != null && ReferenceEquals(rope.Simulation, stepped);

        // ---- Drawing ----------------------------------------------------------------------------------------------
        /// <summary>
        /// A renderer's LateUpdate in frame <paramref name="frame"/>: true when it was drawn by this frame's pass (run
        /// now if it has not run yet); false when it draws itself (its rope is not in an active world, or the pass ran
        /// before the renderer was enabled).
        /// </summary>
        internal static bool OnLateUpdate(RopeMeshRenderer renderer, ElasticRope rope, float alpha, int frame)
        {
            if (renderer.DrawnFrame == frame) return true;
            if (rope is null || rope.WorldIndex < 0 || !IsActive || s_DrawFrame == frame || s_InPass) return false;
            s_DrawFrame = frame;
            Draw(alpha, frame);
            return renderer.DrawnFrame == frame;
        }

        /// <summary>
        /// Draws every enrolled rope with an enabled renderer at <paramref name="alpha"/> between its last two steps:
        /// each renderer interpolates into its arrays and names them to its mesh slot, one parallel fill, each uploads.
        /// </summary>
        internal static void Draw(float alpha, int frame)
        {
            if (!IsActive) return;
            MatchWorkerCount();
            int n = BeginPass();
            try
            {
                for (int k = 0; k < n; k++) Prepare(k, alpha, frame);
                try
                {
                    s_World?.FillMeshes();   // null: every rope was withdrawn while preparing
                }
                catch (InvalidOperationException e)
                {
                    Debug.LogException(e);
                }
                for (int k = 0; k < n; k++)
                {
                    var renderer = s_Drawn[k];
                    var rope = s_Pass[k];
                    if (renderer is null || rope.WorldIndex < 0 || s_World == null || s_World.LastPassFailed(rope.WorldIndex)) continue;
                    try
                    {
                        renderer.UploadWorldFill(s_DrawnSlots[k]);
                    }
                    catch (Exception e)
                    {
                        Debug.LogException(e, renderer);
                    }
                }
            }
            finally
            {
                EndPass(n);
            }
        }

        /// <summary>The main-thread half of drawing the pass's rope <paramref name="k"/>: its renderer fills its slot's caller arrays, or the slot is turned off.</summary>
        static void Prepare(int k, float alpha, int frame)
        {
            var rope = s_Pass[k];
            s_Drawn[k] = null;
            s_DrawnSlots[k] = null;
            if (rope.WorldIndex < 0 || s_World == null) return;
            var renderer = rope.Drawer;
            if (renderer is null || !renderer.isActiveAndEnabled)
            {
                var unused = s_World.GetMeshSlot(rope.WorldIndex);
                if (unused != null) unused.Enabled = false;
                return;
            }
            var slot = s_World.EnableMesh(rope.WorldIndex);
            renderer.DrawnFrame = frame;
            try
            {
                if (!renderer.PrepareWorldFill(alpha, slot)) return;
                s_Drawn[k] = renderer;
                s_DrawnSlots[k] = slot;
            }
            catch (Exception e)
            {
                slot.Enabled = false;
                Debug.LogException(e, renderer);
            }
        }

        // ---- Internals --------------------------------------------------------------------------------------------
        /// <summary>Copies the enrolled ropes into the pass arrays (grown when needed) and marks the pass running; returns their count.</summary>
        static int BeginPass()
        {
            int n = s_Ropes.Count;
            if (s_Pass.Length < n)
            {
                int capacity = Math.Max(n, 2 * s_Pass.Length);
                s_Pass = new ElasticRope[capacity];
                s_Stepped = new RopeSimulation[capacity];
                s_Drawn = new RopeMeshRenderer[capacity];
                s_DrawnSlots = new RopeMeshSlot[capacity];
            }
            for (int k = 0; k < n; k++) s_Pass[k] = s_Ropes[k];
            s_InPass = true;
            return n;
        }

        /// <summary>Ends the pass: drops its references and enrolls the ropes that joined meanwhile.</summary>
        static void EndPass(int n)
        {
            s_InPass = false;
            Array.Clear(s_Pass, 0, n);
            Array.Clear(s_Stepped, 0, n);
            Array.Clear(s_Drawn, 0, n);
            Array.Clear(s_DrawnSlots, 0, n);
            for (int i = 0; i < s_Joining.Count; i++)
                if (s_Joining[i].WantsWorld) Enroll(s_Joining[i]);
            s_Joining.Clear();
        }

        static void CreateWorld()
        {
            s_World = new RopeWorld(WorkerCount);
            for (int i = 0; i < s_Ropes.Count; i++) s_World.Add(s_Ropes[i].Simulation);
            if (s_QuitHooked) return;
            s_QuitHooked = true;
            Application.quitting += Shutdown;
        }

        /// <summary>A new <see cref="WorkerCount"/> replaces the world's threads before the next pass (mesh slots are made again).</summary>
        static void MatchWorkerCount()
        {
            if (s_World == null || s_World.WorkerCount == WorkerCount) return;
            s_World.Dispose();
            s_World = null;
            CreateWorld();
        }

        static void DisposeWorld()
        {
            s_World?.Dispose();
            s_World = null;
            s_StepKey = double.NaN;
            s_DrawFrame = -1;
        }

        static int IndexOf(List<ElasticRope> list, ElasticRope rope)
        {
            for (int i = 0; i < list.Count; i++)
                if (ReferenceEquals(list[i], rope)) return i;
            return -1;
        }
    }
}
