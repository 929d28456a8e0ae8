namespace UnityEngine.TestTools.Constraints
{
    /// <summary>Stand-in of UnityEngine.TestTools.Constraints.Is: NUnit's Is with Unity's extra constraints.</summary>
    public class Is : NUnit.Framework.Is
    {
        /// <summary>A constraint that invokes the delegate given to Assert.That and checks whether it causes any GC memory allocations.</summary>
        public static AllocatingGCMemoryConstraint AllocatingGCMemory() => new AllocatingGCMemoryConstraint();
    }
}
