namespace HookeRope.Solver
{
    /// <summary>Where in a substep a collision pass (<see cref="CollisionSet.Project"/>) runs, which decides what it does besides pushing out.</summary>
    internal enum ContactPass
    {
        /// <summary>After the prediction: resets the substep's normal corrections and detects the contacts of the first chain solve.</summary>
        StartOfSubstep,
        /// <summary>After an iteration that is not the last: detects the contacts of the next chain solve.</summary>
        BetweenIterations,
        /// <summary>After the last iteration: applies friction (no contact detection).</summary>
        LastIteration,
    }
}
