// Google Benchmark timings: the high-accuracy solve and the spline method
// at growing pose counts (one impeller blade sampled ever more finely, with
// the CAM-like U/V distortion), the deviation evaluator, the kinematics per
// pose and the APT reader per megabyte.
//
//   ./build/benchmarks/speed_benchmark --benchmark_repetitions=3
//   (add --benchmark_report_aggregates_only=true for medians only)
#include <sstream>

#include <benchmark/benchmark.h>

#include "apps/huge_page_malloc.h"
#include "model/io/apt_io.h"
#include "model/eval/deviation.h"
#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "solver/fit/bspline_fit.h"
#include "solver/smooth/ceres_smoother.h"
#include "solver/smooth/both_ways_round_poles.h"
#include "solver/spline/spline_smoother.h"

namespace tpopt {
namespace {

struct Blade {
  RuledSurface surface;
  Machine machine;
};

const Blade& SharedBlade() {
  static const Blade blade = [] {
    Blade b;
    const std::string data = std::string(TPOPT_SOURCE_DIR) + "/data/";
    ReadSurfaceJson(data + "surfaces/impeller_blade.json", &b.surface);
    ReadMachineJson(data + "machines/jcde2022_ac.json", &b.machine);
    return b;
  }();
  return blade;
}

ToolPath DistortedPath(int poses) {
  FlankPathOptions g;
  g.poses = poses;
  g.uv_distortion = 0.03;
  ToolPath path;
  GenerateFlankPath(SharedBlade().surface, g, &path);
  return path;
}

void BM_HighAccuracy(benchmark::State& state) {
  const Blade& b = SharedBlade();
  const ToolPath path = DistortedPath(static_cast<int>(state.range(0)));
  ToolPath guess;
  SplineSmootherReport spline_report;
  SmoothWithSplines(path, b.machine, &b.surface, *path.cutter, SplineSmootherOptions(), &guess,
                    &spline_report);
  HighAccuracyOptions options;
  for (auto _ : state) {
    ToolPath out;
    HighAccuracyReport report;
    const SmoothingInputs inputs{&path, &guess, &b.surface, &*path.cutter, &b.machine};
    SmoothBothWaysRoundPoles(inputs, options, &out, &report);
    state.counters["iterations"] = report.iterations;
  }
  state.counters["poses/s"] =
      benchmark::Counter(static_cast<double>(state.range(0)), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_HighAccuracy)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(1);

// Seven passes of the hypar's distorted CAM path (3,000 poses each, a
// rapid before each), every one crossing near the A = 0 pole: each passage
// tried the other way by solving the whole path again (arg 0) or in a
// window round it (arg 1, solver/smooth/both_ways_round_poles.h).
void BM_PolePassages(benchmark::State& state) {
  RuledSurface surface;
  Machine machine;
  const std::string data = std::string(TPOPT_SOURCE_DIR) + "/data/";
  ReadSurfaceJson(data + "surfaces/hypar.json", &surface);
  ReadMachineJson(data + "machines/jcde2022_ac.json", &machine);
  FlankPathOptions g;
  g.poses = 3000;
  g.uv_distortion = 0.03;
  g.axis_noise_deg = 0.3;
  ToolPath pass;
  GenerateFlankPath(surface, g, &pass);
  const ToolPath path = RepeatedPasses(pass, 7);
  ToolPath guess;
  SplineSmootherReport spline_report;
  SmoothWithSplines(path, machine, &surface, *path.cutter,
                    ForHighAccuracyGuess(SplineSmootherOptions()), &guess, &spline_report);
  HighAccuracyOptions options;
  options.pole_window_path_poses = state.range(0) == 0 ? 0 : 5000;
  for (auto _ : state) {
    ToolPath out;
    HighAccuracyReport report;
    const SmoothingInputs inputs{&path, &guess, &surface, &*path.cutter, &machine};
    SmoothBothWaysRoundPoles(inputs, options, &out, &report);
    state.counters["passages"] = report.pole_passages;
    state.counters["rerouted"] = report.pole_passages_rerouted;
    state.counters["in_windows"] = report.pole_passages_in_windows;
    state.counters["final_cost"] = report.final_cost;
  }
}
BENCHMARK(BM_PolePassages)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_Spline(benchmark::State& state) {
  const Blade& b = SharedBlade();
  const ToolPath path = DistortedPath(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    ToolPath out;
    SplineSmootherReport report;
    SmoothWithSplines(path, b.machine, nullptr, *path.cutter, SplineSmootherOptions(), &out,
                      &report);
    benchmark::DoNotOptimize(out.poses.data());
  }
  state.counters["poses/s"] = benchmark::Counter(
      static_cast<double>(state.range(0)) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Spline)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_Deviation(benchmark::State& state) {
  const Blade& b = SharedBlade();
  const ToolPath path = DistortedPath(static_cast<int>(state.range(0)));
  std::vector<JointVector> joints;
  b.machine.AssignJoints(path, &joints);
  for (auto _ : state) {
    DeviationReport report;
    EvaluateDeviation(b.surface, *path.cutter, path, b.machine, joints, DeviationOptions(),
                      &report);
    benchmark::DoNotOptimize(report.max_overcut_mm);
  }
}
BENCHMARK(BM_Deviation)->Arg(300)->Arg(3000)->Unit(benchmark::kMillisecond);

void BM_KinematicsPerPose(benchmark::State& state) {
  const Machine& m = SharedBlade().machine;
  const Eigen::Vector3d p(10, 20, 5);
  double a = 0.3;
  for (auto _ : state) {
    const JointVector j = m.ToJoints(p, a, 0.7);
    Eigen::Vector3d back, axis;
    m.ToWorkpiece(j, &back, &axis);
    benchmark::DoNotOptimize(back);
    a += 1e-9;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_KinematicsPerPose);

void BM_AptRead(benchmark::State& state) {
  const std::string text = FormatApt(DistortedPath(100000));
  for (auto _ : state) {
    std::istringstream in(text);
    ToolPath path;
    std::vector<std::string> warnings;
    ReadAptStream(in, "bench.cls", &path, &warnings);
    benchmark::DoNotOptimize(path.poses.data());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_AptRead)->Unit(benchmark::kMillisecond);

// The seed-004 window fit (target: <= 1 us a window): 4 CL points on a
// helix with exact tangents in, 6 control points out. Windows cycle over
// 1,024 prepared ones so that the data are not one cached constant.
void BM_FitWindow(benchmark::State& state) {
  const bool from_neighbours = state.range(0) != 0;
  constexpr int kWindows = 1024;
  std::vector<std::array<Eigen::Vector3d, 4>> points(kWindows), tangents(kWindows);
  const double speed = std::hypot(10.0, 2.0);
  for (int w = 0; w < kWindows; ++w) {
    for (int k = 0; k < 4; ++k) {
      const double t = (0.4 * (w + k) + 0.1 * ((w * 7 + k * 3) % 5)) / speed;
      points[w][k] = {10 * std::cos(t), 10 * std::sin(t), 2 * t};
      tangents[w][k] = Eigen::Vector3d(-10 * std::sin(t), 10 * std::cos(t), 2) / speed;
    }
  }
  LocalFitOptions options;
  options.chord_height = from_neighbours ? ChordHeight::kFromNeighbours : ChordHeight::kFixed;
  WindowFit fit;
  int w = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(FitWindow(points[w], tangents[w], options, 0, &fit).ok());
    benchmark::DoNotOptimize(fit.control_points[2]);
    w = (w + 1) & (kWindows - 1);
  }
  state.SetLabel(from_neighbours ? "approx. arc, delta from neighbours"
                                 : "approx. arc, fixed delta (seed)");
}
BENCHMARK(BM_FitWindow)->Arg(0)->Arg(1)->Unit(benchmark::kNanosecond);

}  // namespace
}  // namespace tpopt

// BENCHMARK_MAIN, with the program first restarted for huge pages as tpopt
// is, so that the timings are those of the command.
int main(int argc, char** argv) {
  tpopt::RestartWithHugePageMalloc(argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
