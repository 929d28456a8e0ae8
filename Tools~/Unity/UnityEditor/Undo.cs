namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.Undo: lets you register undo operations on specific objects you are about to perform changes on.</summary>
    public class Undo
    {
        /// <summary>Register an undo operations for a newly created object.</summary>
        public static void RegisterCreatedObjectUndo(UnityEngine.Object objectToUndo, string name) => throw Shim.NotRun;

        /// <summary>Records any changes done on the object after the RecordObject function.</summary>
        public static void RecordObject(UnityEngine.Object objectToUndo, string name) => throw Shim.NotRun;
    }
}
