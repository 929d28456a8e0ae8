using System.Linq;
using BenchmarkDotNet.Columns;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;

namespace HookeRope.Bench
{
    /// <summary>
    /// "ns/unit": the mean time of one invocation divided by the work units it performs — segment-iterations
    /// (segments × substeps × iterations) for a step, as reported by each benchmark's <c>Units</c> parameter.
    /// </summary>
    public sealed class PerUnitColumn : IColumn
    {
        public string Id => "PerUnit";
        public string ColumnName => "ns/unit";
        public bool AlwaysShow => true;
        public ColumnCategory Category => ColumnCategory.Custom;
        public int PriorityInCategory => 0;
        public bool IsNumeric => true;
        public UnitType UnitType => UnitType.Dimensionless;
        public string Legend => "Mean time per segment-iteration (segments x substeps x iterations per invocation), ns";

        public string GetValue(Summary summary, BenchmarkCase benchmarkCase)
        {
            var report = summary[benchmarkCase];
            if (report?.ResultStatistics == null) return "-";
            object instance = System.Activator.CreateInstance(benchmarkCase.Descriptor.Type);
            foreach (var parameter in benchmarkCase.Parameters.Items)
                benchmarkCase.Descriptor.Type.GetProperty(parameter.Name)?.SetValue(instance, parameter.Value);
            if (!(instance is IUnitCount counted)) return "-";
            return (report.ResultStatistics.Mean / counted.Units).ToString("F2");
        }

        public string GetValue(Summary summary, BenchmarkCase benchmarkCase, SummaryStyle style) => GetValue(summary, benchmarkCase);
        public bool IsDefault(Summary summary, BenchmarkCase benchmarkCase) => false;
        public bool IsAvailable(Summary summary) => summary.BenchmarksCases.Any(b => typeof(IUnitCount).IsAssignableFrom(b.Descriptor.Type));
    }

    /// <summary>A benchmark class that knows how many work units one invocation performs.</summary>
    public interface IUnitCount
    {
        double Units { get; }
    }
}
