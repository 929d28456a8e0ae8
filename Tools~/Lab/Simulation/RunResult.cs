using System.Collections.Generic;
using HookeRope.Lab.Scenarios;

namespace HookeRope.Lab.Simulation
{
    /// <summary>One CSV row: the state of the rope after a host step (SI units).</summary>
    public struct Sample
    {
        /// <summary>Simulated time in s.</summary>
        public double Time;
        /// <summary>Position of the end particle (the load) in m.</summary>
        public double X, Y, Z;
        /// <summary>Velocity of the end particle in m/s.</summary>
        public double VX, VY, VZ;
        /// <summary>Tension of the first segment in N (the anchor force).</summary>
        public double TopTension;
        /// <summary>Tension of the last segment in N (the force on the load).</summary>
        public double BottomTension;
        /// <summary>Current length of the intact rope minus its rest length, in m.</summary>
        public double Elongation;
        /// <summary>Smallest particle radius in m.</summary>
        public double MinRadius;
        /// <summary>Radius at the neck (the defect) in m, or the minimum when there is no neck.</summary>
        public double NeckRadius;
        /// <summary>True once any segment or pin has broken.</summary>
        public bool Broken;
        /// <summary>Solver residual (largest strain error) of the step.</summary>
        public double Residual;
        /// <summary>Total energy in J.</summary>
        public double Energy;
        /// <summary>Largest first-segment tension in N over every substep since the previous sample (<see cref="HookeRope.Solver.Rope.PeakTensions"/>).</summary>
        public double TopTensionMax;
        /// <summary>Mean first-segment tension in N over every substep since the previous sample (<see cref="HookeRope.Solver.Rope.MeanTensions"/>).</summary>
        public double TopTensionMean;
        /// <summary>Largest last-segment tension in N over every substep since the previous sample.</summary>
        public double BottomTensionMax;
        /// <summary>Mean last-segment tension in N over every substep since the previous sample.</summary>
        public double BottomTensionMean;
    }

    /// <summary>Radius along the rope at one instant.</summary>
    public sealed class RadiusProfile
    {
        /// <summary>Simulated time in s.</summary>
        public double Time;
        /// <summary>Why this instant: "" for outputs.profileTimes, else "neck onset", "thinnest (intact)" or "break".</summary>
        public string Label = "";
        /// <summary>Rest arc length of each particle from the start, m.</summary>
        public double[] Arc;
        /// <summary>Particle radius in m.</summary>
        public double[] Radius;
    }

    /// <summary>A tube mesh captured at one instant (for glTF export).</summary>
    public sealed class MeshSnapshot
    {
        /// <summary>Simulated time in s.</summary>
        public double Time;
        /// <summary>Interleaved vertices: position(3), normal(3), tangent(4), uv(2).</summary>
        public float[] Vertices;
        /// <summary>Triangle indices: the tube and caps first, then the burr fibres.</summary>
        public int[] Indices;
        /// <summary>Indices of the tube and caps, [0, TubeIndexCount); the rest are burr fibres (their own material).</summary>
        public int TubeIndexCount;
    }

    /// <summary>Everything a run produced: samples, profiles, meshes and headline numbers.</summary>
    public sealed class RunResult
    {
        /// <summary>The scenario that ran.</summary>
        public Scenario Scenario;
        /// <summary>Time series (one entry per CSV row).</summary>
        public List<Sample> Samples = new List<Sample>();
        /// <summary>Timed events as they were applied.</summary>
        public List<AppliedEvent> Events = new List<AppliedEvent>();
        /// <summary>Radius profiles at outputs.profileTimes.</summary>
        public List<RadiusProfile> Profiles = new List<RadiusProfile>();
        /// <summary>Radius profiles at the moments that matter, found during the run: neck onset, the thinnest intact state, the break.</summary>
        public List<RadiusProfile> KeyProfiles = new List<RadiusProfile>();
        /// <summary>Meshes at outputs.gltfTimes.</summary>
        public List<MeshSnapshot> Meshes = new List<MeshSnapshot>();
        /// <summary>Largest anchor force in N.</summary>
        public double PeakTopForce;
        /// <summary>Largest force on the load in N.</summary>
        public double PeakLoadForce;
        /// <summary>Largest elongation in m.</summary>
        public double MaxElongation;
        /// <summary>Distance the load fell from release to its lowest point, m.</summary>
        public double TotalDrop;
        /// <summary>Distance the load travelled from the first taut instant to its lowest point, m.</summary>
        public double ArrestDistance;
        /// <summary>Time the rope first carried load (s), or NaN.</summary>
        public double TautTime = double.NaN;
        /// <summary>Time of the first break (s), or NaN.</summary>
        public double BreakTime = double.NaN;
        /// <summary>True when the rope broke while it was built (its initial stretch already past the break criterion).</summary>
        public bool BrokenAtConstruction;
        /// <summary>Tension just before the first break in N, or NaN.</summary>
        public double BreakTension = double.NaN;
        /// <summary>Largest residual over the run.</summary>
        public double MaxResidual;
        /// <summary>True if any position became NaN or infinite.</summary>
        public bool NonFinite;
        /// <summary>Energy at the start and the largest energy seen, J.</summary>
        public double InitialEnergy, MaxEnergy;
        /// <summary>Largest energy over the second half of the run, J (a lasting rise, not a transient).</summary>
        public double LateMaxEnergy = double.NegativeInfinity;
        /// <summary>Largest energy over the first half of the run, J.</summary>
        public double EarlyMaxEnergy = double.NegativeInfinity;
        /// <summary>Largest kinetic + gravitational energy over the second half of the run, J.</summary>
        public double LateMaxMotionEnergy = double.NegativeInfinity;
        /// <summary>Largest kinetic + gravitational energy over the first half of the run, J.</summary>
        public double EarlyMaxMotionEnergy = double.NegativeInfinity;
        /// <summary>Wall-clock time of the stepping loop in s.</summary>
        public double WallSeconds;
        /// <summary>Host steps taken.</summary>
        public int Steps;
        /// <summary>Final particle positions in m (x, y, z per particle).</summary>
        public double[] FinalPositions;
        /// <summary>Final collision radius of each particle in m (what the solver collides with: the radius model's Poisson-thinned or necked radius).</summary>
        public double[] FinalRadii;
        /// <summary>Largest particle speed after the last step, m/s.</summary>
        public double FinalMaxSpeed;
        /// <summary>Largest distance of any particle from the start anchor during the run, m.</summary>
        public double MaxExtent;
        /// <summary>Final segment tensions in N.</summary>
        public double[] FinalTensions;
        /// <summary>Drop of the end particle along gravity since release after each host step, m.</summary>
        public double[] LoadDrop;
        /// <summary>Tension of the first segment after each host step, N.</summary>
        public double[] TopTensionSeries;
        /// <summary>Largest first-segment (anchor) tension over the substeps of each host step, N (<see cref="HookeRope.Solver.Rope.PeakTensions"/>; 0 once that segment broke).</summary>
        public double[] PeakTopTensionSeries;
        /// <summary>True when the run evaluated the energy every host step (<see cref="RunOptions.TrackEnergy"/>): <see cref="InitialEnergy"/> and <see cref="MaxEnergy"/> are measured.</summary>
        public bool EnergyTracked;
        /// <summary>Energy absorber deployment at the end of the run (m; 0 without one).</summary>
        public double AbsorberDeployment;
        /// <summary>Permanent set at the end of the run (m): Σ (L_p − L) over the intact segments, absorber included.</summary>
        public double PlasticElongation;
        /// <summary>Plastic work at the end of the run (J).</summary>
        public double PlasticWork;
        /// <summary>Solver residual (strain error, dimensionless) after each host step.</summary>
        public float[] ResidualSeries;
        /// <summary>Elongation after each host step, m.</summary>
        public double[] ElongationSeries;
        /// <summary>
        /// "settle" runs only (else null): after each host step, the horizontal offset (m) of the rope's centre of mass from the
        /// vertical through the start, signed along its initial direction, and the largest horizontal distance of a particle from it.
        /// </summary>
        public double[] SwingSeries, OffVerticalSeries;
        /// <summary>Host step in s (series index k is time (k + 1)·HostStep).</summary>
        public double HostStep;
        /// <summary>Final force of the rope on the start and end loads in N (zero without a load).</summary>
        public double[] StartLoadForce = new double[3], EndLoadForce = new double[3];
        /// <summary>Final pin forces in N (start, end), zero when not pinned.</summary>
        public double[] StartPinForce = new double[3], EndPinForce = new double[3];
    }
}
