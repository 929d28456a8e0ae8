using System.Collections.Generic;
using System.Globalization;
using HookeRope.Solver;
using UnityEditor;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// Inspector of <see cref="ElasticRope"/>, grouped Material / Material law / Geometry / Solver / Attachments / Collisions /
    /// Drag / Fracture / Read-outs (the material law with its force–elongation preview: <see cref="MaterialLawInspector"/>). Warns when the settings predict a large stretch error and previews the static
    /// sag in edit mode. Read-outs repaint live in Play; with several ropes selected they show a table with one
    /// column per rope (<see cref="RopeReadoutTable"/>). Attachments has "Attach Start/End to selection"
    /// (<see cref="RopeAttachToSelection"/>); the Scene view shows a position handle per attached end (<see cref="RopeEndHandles"/>).
    /// </summary>
    [CustomEditor(typeof(ElasticRope)), CanEditMultipleObjects]
    sealed class ElasticRopeEditor : UnityEditor.Editor
    {
        static bool s_Material = true, s_Geometry = true, s_Solver = true, s_Attachments = true, s_Collisions, s_Drag, s_Fracture, s_Readouts = true;
        static bool s_MaterialLaw = true;
        MaterialLawInspector m_MaterialLaw;

        SerializedProperty m_StiffnessInput, m_YoungsModulus, m_AxialStiffness, m_Density, m_PoissonRatio, m_Damping;
        SerializedProperty m_RestLength, m_Radius, m_SegmentCount;
        SerializedProperty m_Solver, m_Substeps, m_Iterations, m_TensionModel, m_Integrator, m_GaussSeidelKernel, m_Gravity;
        SerializedProperty m_Start, m_End, m_AttachmentCompliance, m_OnStepped;
        SerializedProperty m_CollisionMode, m_Colliders, m_CollisionLayers, m_Planes, m_Friction;
        SerializedProperty m_ViscousDrag, m_DragCoefficient, m_SkinFriction, m_AirDensity, m_Wind;
        SerializedProperty m_RadiusModel, m_Necking, m_NeckMode, m_NeckRadiusFraction, m_DefectPosition, m_Fracture, m_BreakStrain, m_BreakRadiusFraction, m_OnBreak;

        void OnEnable()
        {
            var so = serializedObject;
            m_StiffnessInput = so.FindProperty(nameof(m_StiffnessInput));
            m_YoungsModulus = so.FindProperty(nameof(m_YoungsModulus));
            m_AxialStiffness = so.FindProperty(nameof(m_AxialStiffness));
            m_Density = so.FindProperty(nameof(m_Density));
            m_PoissonRatio = so.FindProperty(nameof(m_PoissonRatio));
            m_Damping = so.FindProperty(nameof(m_Damping));
            m_RestLength = so.FindProperty(nameof(m_RestLength));
            m_Radius = so.FindProperty(nameof(m_Radius));
            m_SegmentCount = so.FindProperty(nameof(m_SegmentCount));
            m_Solver = so.FindProperty(nameof(m_Solver));
            m_Substeps = so.FindProperty(nameof(m_Substeps));
            m_Iterations = so.FindProperty(nameof(m_Iterations));
            m_TensionModel = so.FindProperty(nameof(m_TensionModel));
            m_Integrator = so.FindProperty(nameof(m_Integrator));
            m_GaussSeidelKernel = so.FindProperty(nameof(m_GaussSeidelKernel));
            m_Gravity = so.FindProperty(nameof(m_Gravity));
            m_Start = so.FindProperty(nameof(m_Start));
            m_End = so.FindProperty(nameof(m_End));
            m_AttachmentCompliance = so.FindProperty(nameof(m_AttachmentCompliance));
            m_OnStepped = so.FindProperty(nameof(m_OnStepped));
            m_CollisionMode = so.FindProperty(nameof(m_CollisionMode));
            m_Colliders = so.FindProperty(nameof(m_Colliders));
            m_CollisionLayers = so.FindProperty(nameof(m_CollisionLayers));
            m_Planes = so.FindProperty(nameof(m_Planes));
            m_Friction = so.FindProperty(nameof(m_Friction));
            m_ViscousDrag = so.FindProperty(nameof(m_ViscousDrag));
            m_DragCoefficient = so.FindProperty(nameof(m_DragCoefficient));
            m_SkinFriction = so.FindProperty(nameof(m_SkinFriction));
            m_AirDensity = so.FindProperty(nameof(m_AirDensity));
            m_Wind = so.FindProperty(nameof(m_Wind));
            m_RadiusModel = so.FindProperty(nameof(m_RadiusModel));
            m_Necking = so.FindProperty(nameof(m_Necking));
            m_NeckMode = so.FindProperty(nameof(m_NeckMode));
            m_NeckRadiusFraction = so.FindProperty(nameof(m_NeckRadiusFraction));
            m_DefectPosition = so.FindProperty(nameof(m_DefectPosition));
            m_Fracture = so.FindProperty(nameof(m_Fracture));
            m_BreakStrain = so.FindProperty(nameof(m_BreakStrain));
            m_BreakRadiusFraction = so.FindProperty(nameof(m_BreakRadiusFraction));
            m_OnBreak = so.FindProperty(nameof(m_OnBreak));
            m_MaterialLaw = new MaterialLawInspector(so);
        }

        public override bool RequiresConstantRepaint() => EditorApplication.isPlaying;

        public override void OnInspectorGUI()
        {
            serializedObject.Update();
            var rope = (ElasticRope)target;

            if (Section(ref s_Material, "Material"))
            {
                Field(m_StiffnessInput);
                Field(m_StiffnessInput.intValue == (int)RopeStiffnessInput.AxialStiffness ? m_AxialStiffness : m_YoungsModulus);
                Field(m_Density);
                Field(m_PoissonRatio);
                Field(m_Damping);
                EditorGUILayout.LabelField("Axial stiffness E·A", Format(rope.AxialStiffness, "N"));
                EditorGUILayout.LabelField("Mass per metre", Format(rope.LinearDensity, "kg/m"));
            }
            if (Section(ref s_MaterialLaw, "Material law (yield, necking, energy absorber)"))
                m_MaterialLaw.Draw(rope, !serializedObject.isEditingMultipleObjects);
            if (Section(ref s_Geometry, "Geometry"))
            {
                Field(m_RestLength);
                Field(m_Radius);
                Field(m_SegmentCount);
            }
            if (Section(ref s_Solver, "Solver"))
            {
                Field(m_Solver);
                Field(m_Substeps);
                Field(m_Iterations);
                Field(m_TensionModel);
                Field(m_Integrator);
                if (m_Solver.hasMultipleDifferentValues || m_Solver.intValue == (int)ConstraintSolverKind.GaussSeidel) Field(m_GaussSeidelKernel);
                Field(m_Gravity);
                StretchWarning(rope);
            }
            if (Section(ref s_Attachments, "Attachments"))
            {
                if (!serializedObject.isEditingMultipleObjects) AttachFixBox(rope);
                EditorGUILayout.PropertyField(m_Start, includeChildren: true);
                EditorGUILayout.PropertyField(m_End, includeChildren: true);
                AttachToSelectionButtons();
                Field(m_AttachmentCompliance);
                EditorGUILayout.PropertyField(m_OnStepped, includeChildren: true);
                EditorGUI.BeginDisabledGroup(EditorApplication.isPlaying || serializedObject.isEditingMultipleObjects);
                if (GUILayout.Button("Preview static sag")) StaticSagPreview.Compute(rope);
                EditorGUI.EndDisabledGroup();
            }
            if (Section(ref s_Collisions, "Collisions"))
            {
                Field(m_CollisionMode);
                if (m_CollisionMode.intValue == (int)RopeCollisionMode.ListedColliders) EditorGUILayout.PropertyField(m_Colliders, includeChildren: true);
                if (m_CollisionMode.intValue == (int)RopeCollisionMode.LayerMask) Field(m_CollisionLayers);
                if (m_CollisionMode.intValue != (int)RopeCollisionMode.Off)
                {
                    EditorGUILayout.PropertyField(m_Planes, includeChildren: true);
                    Field(m_Friction);
                }
            }
            if (Section(ref s_Drag, "Drag"))
            {
                Field(m_ViscousDrag);
                Field(m_DragCoefficient);
                Field(m_SkinFriction);
                Field(m_AirDensity);
                Field(m_Wind);
                DragPreview(rope);
            }
            if (Section(ref s_Fracture, "Fracture (thinning, necking, break)"))
            {
                Field(m_RadiusModel);
                Field(m_Necking);
                EditorGUI.BeginDisabledGroup(!m_Necking.boolValue);
                Field(m_NeckMode);
                Field(m_NeckRadiusFraction);
                EditorGUI.EndDisabledGroup();
                Field(m_DefectPosition);
                Field(m_Fracture);
                EditorGUI.BeginDisabledGroup(!m_Fracture.boolValue);
                Field(m_BreakStrain);
                Field(m_BreakRadiusFraction);
                EditorGUI.EndDisabledGroup();
                EditorGUILayout.PropertyField(m_OnBreak, includeChildren: true);
            }
            if (Section(ref s_Readouts, "Read-outs"))
                Readouts();

            serializedObject.ApplyModifiedProperties();
        }

        static bool Section(ref bool open, string title)
        {
            open = EditorGUILayout.Foldout(open, title, toggleOnLabelClick: true);
            return open;
        }

        static void Field(SerializedProperty property) => EditorGUILayout.PropertyField(property);

        static string Format(float value, string unit) => RopeReadoutTable.Format(value, unit);

        void StretchWarning(ElasticRope rope)
        {
            float endMass = rope.EndAttachment.Body != null ? rope.EndAttachment.Body.mass : 0f;
            double error = StretchErrorEstimate.Predict(rope.SegmentCount, rope.RestLength, rope.AxialStiffness, rope.LinearDensity,
                endMass, Time.fixedDeltaTime, rope.Substeps, rope.Iterations, rope.Solver);
            if (error > StretchErrorEstimate.WarningThreshold)
                EditorGUILayout.HelpBox(string.Format(CultureInfo.InvariantCulture,
                    "These settings predict the rope to stretch about {0:P0} more than the material allows (Gauss-Seidel, {1} substeps × {2} iterations for {3} segments). Use the Exact Chain solver, or raise substeps.",
                    error, rope.Substeps, rope.Iterations, rope.SegmentCount), MessageType.Warning);
        }

        /// <summary>What the drag settings mean for this rope (uniform, <see cref="DragLaw"/>): how fast a swing decays, how fast it falls broadside.</summary>
        static void DragPreview(ElasticRope rope)
        {
            double mu = rope.LinearDensity;
            double rate = DragLaw.SwingDecayRate(rope.ViscousDrag, mu);
            EditorGUILayout.LabelField("Swing amplitude 1/e after", rate > 0.0 ? Format((float)(1.0 / rate), "s") : "never (no viscous drag)");
            double terminal = DragLaw.BroadsideTerminalVelocity(rope.ViscousDrag, rope.DragCoefficient, rope.AirDensity, rope.Radius, mu, rope.Gravity.magnitude);
            EditorGUILayout.LabelField("Falls broadside at most", double.IsInfinity(terminal) ? "no limit (no drag)" : Format((float)terminal, "m/s"));
        }

        void AttachFixBox(ElasticRope rope)
        {
            var fix = RopeAttachFix.For(rope);
            if (fix == null) return;
            EditorGUILayout.HelpBox(fix.Message, MessageType.Warning);
            if (!GUILayout.Button(fix.ButtonLabel)) return;
            fix.Apply();
            serializedObject.Update();
        }

        /// <summary>Scene view: a position handle on each attached end (called once per selected rope, with target set to it).</summary>
        void OnSceneGUI() => RopeEndHandles.Draw((ElasticRope)target, s_PositionHandle);

        static readonly System.Func<Vector3, Vector3> s_PositionHandle = position => Handles.PositionHandle(position, Quaternion.identity);

        void AttachToSelectionButtons()
        {
            var ropes = new ElasticRope[targets.Length];
            for (int i = 0; i < ropes.Length; i++) ropes[i] = (ElasticRope)targets[i];
            var selection = Selection.activeTransform;
            string unavailable = RopeAttachToSelection.Unavailable(ropes, selection);
            EditorGUI.BeginDisabledGroup(unavailable != null);
            bool start = GUILayout.Button(RopeAttachToSelection.AttachStartName);
            bool end = GUILayout.Button(RopeAttachToSelection.AttachEndName);
            EditorGUI.EndDisabledGroup();
            if (unavailable != null) EditorGUILayout.HelpBox(unavailable, MessageType.None);
            if (!start && !end) return;
            foreach (var rope in ropes)
                RopeAttachToSelection.Attach(rope, start ? rope.StartAttachment : rope.EndAttachment, selection,
                    start ? RopeAttachToSelection.AttachStartName : RopeAttachToSelection.AttachEndName);
            serializedObject.Update();
        }

        void Readouts()
        {
            var ropes = new List<ElasticRope>(targets.Length);
            foreach (var t in targets)
                if (t is ElasticRope rope) ropes.Add(rope);
            bool anyBuilt = false;
            foreach (var rope in ropes) anyBuilt |= rope.IsBuilt;
            if (!anyBuilt)
            {
                EditorGUILayout.HelpBox("Read-outs appear in Play (or after ElasticRope.Rebuild()).", MessageType.Info);
                return;
            }
            if (EditorApplication.isPlaying && GUILayout.Button(ropes.Count > 1 ? "Rebuild all" : "Rebuild"))
                foreach (var rope in ropes) rope.Rebuild();
            var rows = RopeReadoutTable.Build(ropes);
            // One rope: label and value. Several: a table, one " | "-separated column per rope, headed by the names.
            for (int i = ropes.Count > 1 ? 0 : 1; i < rows.Count; i++)
                EditorGUILayout.LabelField(rows[i].Label, rows[i].Joined);
        }
    }
}
