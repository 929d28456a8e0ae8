using HookeRope.Solver;
using UnityEditor;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// The inspector's "Material law" section of <see cref="ElasticRope"/> (issue 15): the material model and its plastic
    /// law, the energy absorber, and the force–elongation curve preview. The geometry is <see cref="ForceElongationPreview"/>;
    /// this class only lays out the fields and makes the drawing calls.
    /// </summary>
    internal sealed class MaterialLawInspector
    {
        static readonly Color s_Background = new Color(0.16f, 0.16f, 0.16f, 1f);
        static readonly Color s_Axis = new Color(0.45f, 0.45f, 0.45f, 1f);
        static readonly Color s_Curve = new Color(0.93f, 0.5f, 0.12f, 1f);

        readonly SerializedProperty m_MaterialModel, m_YieldStrain, m_HardeningModulus, m_NeckingStrain, m_UltimateStrain;
        readonly SerializedProperty m_EnergyAbsorber, m_AbsorberForce, m_AbsorberDeployment;

        public MaterialLawInspector(SerializedObject so)
        {
            m_MaterialModel = so.FindProperty(nameof(m_MaterialModel));
            m_YieldStrain = so.FindProperty(nameof(m_YieldStrain));
            m_HardeningModulus = so.FindProperty(nameof(m_HardeningModulus));
            m_NeckingStrain = so.FindProperty(nameof(m_NeckingStrain));
            m_UltimateStrain = so.FindProperty(nameof(m_UltimateStrain));
            m_EnergyAbsorber = so.FindProperty(nameof(m_EnergyAbsorber));
            m_AbsorberForce = so.FindProperty(nameof(m_AbsorberForce));
            m_AbsorberDeployment = so.FindProperty(nameof(m_AbsorberDeployment));
        }

        /// <summary>The fields, the yield force and the preview of <paramref name="rope"/>'s curve (one rope selected).</summary>
        public void Draw(ElasticRope rope, bool single)
        {
            EditorGUILayout.PropertyField(m_MaterialModel);
            EditorGUI.BeginDisabledGroup(m_MaterialModel.intValue != (int)MaterialModel.ElasticPlastic);
            EditorGUILayout.PropertyField(m_YieldStrain);
            EditorGUILayout.LabelField("Yield force E·A·ε_y", RopeReadoutTable.Format(rope.AxialStiffness * rope.YieldStrain, "N"));
            EditorGUILayout.PropertyField(m_HardeningModulus);
            EditorGUILayout.PropertyField(m_NeckingStrain);
            EditorGUILayout.PropertyField(m_UltimateStrain);
            EditorGUI.EndDisabledGroup();
            EditorGUILayout.PropertyField(m_EnergyAbsorber);
            EditorGUI.BeginDisabledGroup(!m_EnergyAbsorber.boolValue);
            EditorGUILayout.PropertyField(m_AbsorberForce);
            EditorGUILayout.PropertyField(m_AbsorberDeployment);
            EditorGUI.EndDisabledGroup();
            if (single) Preview(rope.ForceElongationCurve());
        }

        /// <summary>The curve preview: a dark rectangle, its two axes and the curve (the thin drawing calls).</summary>
        static void Preview(ForceElongationCurve curve)
        {
            Rect area = GUILayoutUtility.GetRect(10f, 10000f, ForceElongationPreview.Height, ForceElongationPreview.Height);
            EditorGUI.DrawRect(area, s_Background);
            Handles.color = s_Axis;
            Handles.DrawAAPolyLine(1f, new Vector3(area.xMin, area.yMin, 0f), new Vector3(area.xMin, area.yMax, 0f), new Vector3(area.xMax, area.yMax, 0f));
            Handles.color = s_Curve;
            Handles.DrawAAPolyLine(2f, ForceElongationPreview.Points(curve, area.x, area.y, area.width, area.height));
            EditorGUILayout.LabelField("Force–elongation (slow pull)", ForceElongationPreview.Caption(curve));
        }
    }
}
