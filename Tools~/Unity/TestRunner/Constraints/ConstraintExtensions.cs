using NUnit.Framework.Constraints;

namespace UnityEngine.TestTools.Constraints
{
    /// <summary>Stand-in of UnityEngine.TestTools.Constraints.ConstraintExtensions: Unity's constraints in NUnit constraint chains (Is.Not.AllocatingGCMemory()).</summary>
    public static class ConstraintExtensions
    {
        /// <summary>Appends an <see cref="AllocatingGCMemoryConstraint"/> to the chain.</summary>
        public static AllocatingGCMemoryConstraint AllocatingGCMemory(this ConstraintExpression chain)
        {
            var constraint = new AllocatingGCMemoryConstraint();
            chain.Append(constraint);
            return constraint;
        }
    }
}
