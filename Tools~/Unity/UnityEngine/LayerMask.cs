using System;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.LayerMask: a 32-bit mask of layers, used by physics queries. Layer names are Unity's
    /// builtin layers (0 Default, 1 TransparentFX, 2 Ignore Raycast, 4 Water, 5 UI); the stand-in has no Tag Manager,
    /// so user layers (3, 6–31) have no name.
    /// </summary>
    public struct LayerMask
    {
        static readonly string[] s_BuiltinNames = { "Default", "TransparentFX", "Ignore Raycast", "", "Water", "UI" };

        int m_Mask;

        /// <summary>Converts a layer mask value to an integer value.</summary>
        public int value
        {
            get => m_Mask;
            set => m_Mask = value;
        }

        /// <summary>Implicitly converts a LayerMask to an integer.</summary>
        public static implicit operator int(LayerMask mask) => mask.m_Mask;

        /// <summary>Implicitly converts an integer to a LayerMask.</summary>
        public static implicit operator LayerMask(int intVal)
        {
            LayerMask mask;
            mask.m_Mask = intVal;
            return mask;
        }

        /// <summary>Given a layer number, returns the name of the layer as defined in either a Builtin or a User Layer in the Tag Manager.</summary>
        public static string LayerToName(int layer) => layer >= 0 && layer < s_BuiltinNames.Length ? s_BuiltinNames[layer] : "";

        /// <summary>Given a layer name, returns the layer index as defined by either a Builtin or a User Layer in the Tag Manager.</summary>
        public static int NameToLayer(string layerName)
        {
            if (string.IsNullOrEmpty(layerName)) return -1;
            for (int i = 0; i < s_BuiltinNames.Length; i++)
                if (s_BuiltinNames[i] == layerName) return i;
            return -1;
        }

        /// <summary>Given a set of layer names as defined by either a Builtin or a User Layer in the Tag Manager, returns the equivalent layer mask for all of them.</summary>
        public static int GetMask(params string[] layerNames)
        {
            if (layerNames == null) throw new ArgumentNullException(nameof(layerNames));
            int mask = 0;
            for (int i = 0; i < layerNames.Length; i++)
            {
                int layer = NameToLayer(layerNames[i]);
                if (layer != -1) mask |= 1 << layer;
            }
            return mask;
        }
    }
}
