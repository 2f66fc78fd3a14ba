// The parametrisation table of the README: the seed-004 local fit with
// uniform, chord-length, centripetal and approximate-arc knots (the seed's
// fixed chord height, and ours from neighbour circles), against straight
// segments and a global least-squares fit, on CL data whose ideal curve is
// known: an unevenly sampled helix, an ellipse sampled evenly in angle,
// and the pencil example under the seed's conditions.
//
//   ./build/benchmarks/parametrization_benchmark   (prints markdown)
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>

#include "model/io/pencil_job.h"
#include "model/path/pencil_path.h"
#include "solver/fit/pencil_fit.h"
#include "solver/fit/bspline_least_squares.h"
#include "solver/fit/span_error.h"

namespace tpopt {
namespace {

constexpr int kSamplesPerSpan = 15;

struct Dataset {
  std::string name;
  std::vector<Eigen::Vector3d> points, tangents;
  IdealCurve ideal;
};

// Helix of radius 10 mm and 2 mm rise per radian at random steps of
// 0.1 to 0.7 mm of arc (a CAM path's uneven spacing).
Dataset Helix() {
  Dataset d;
  d.name = "helix r 10, steps 0.1-0.7 mm";
  const double speed = std::hypot(10.0, 2.0);
  auto point = [speed](double s) {
    const double t = s / speed;
    return Eigen::Vector3d(10 * std::cos(t), 10 * std::sin(t), 2 * t);
  };
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> step(0.1, 0.7);
  auto arcs = std::make_shared<std::vector<double>>();
  for (double s = 0; arcs->size() < 200; s += step(rng)) {
    arcs->push_back(s);
    d.points.push_back(point(s));
    const double t = s / speed;
    d.tangents.push_back(Eigen::Vector3d(-10 * std::sin(t), 10 * std::cos(t), 2) / speed);
  }
  d.ideal = [arcs, point](size_t i, double x) {
    return point((*arcs)[i] + x * ((*arcs)[i + 1] - (*arcs)[i]));
  };
  return d;
}

// Ellipse 30 x 10 mm at 400 even angle steps: arc steps from 0.16 to 0.47
// mm, curvature radii from 3.3 to 90 mm.
Dataset Ellipse() {
  Dataset d;
  d.name = "ellipse 30 x 10, even angle";
  auto point = [](double a) { return Eigen::Vector3d(30 * std::cos(a), 10 * std::sin(a), 0); };
  const int n = 400;
  const double step = 2 * M_PI / n;
  for (int k = 0; k < n; ++k) {
    const double a = k * step;
    d.points.push_back(point(a));
    d.tangents.push_back(Eigen::Vector3d(-30 * std::sin(a), 10 * std::cos(a), 0).normalized());
  }
  d.ideal = [point, step](size_t i, double x) { return point((i + x) * step); };
  return d;
}

Status Pencil(const PencilJob& job, std::vector<PencilRun>* runs, Dataset* d) {
  PencilOptions options;  // 3000 mm/min, 8 ms, 3 mm ball
  RETURN_IF_ERROR(GeneratePencilRuns(job.geometry, job.guides, options, runs));
  d->name = "pencil flower, 0.4 mm (seed)";
  for (const PencilPoint& p : (*runs)[0].points) {
    d->points.push_back(p.cl);
    d->tangents.push_back(p.dcl_dm.normalized());
  }
  d->ideal = IdealPencilCurve(job.geometry, job.guides[0], (*runs)[0]);
  return Status::Ok();
}

struct LocalMethod {
  const char* name;
  Parametrization parametrization;
  ChordHeight chord_height;
};

void PrintLocalRows(const Dataset& d) {
  const LocalMethod methods[] = {
      {"local, uniform", Parametrization::kUniform, ChordHeight::kFixed},
      {"local, chord length", Parametrization::kChordLength, ChordHeight::kFixed},
      {"local, centripetal", Parametrization::kCentripetal, ChordHeight::kFixed},
      {"local, approx. arc, delta = 1 um (seed)", Parametrization::kApproximateArc,
       ChordHeight::kFixed},
      {"local, approx. arc, delta from neighbours", Parametrization::kApproximateArc,
       ChordHeight::kFromNeighbours},
  };
  for (const LocalMethod& m : methods) {
    LocalFitOptions options;
    options.parametrization = m.parametrization;
    options.chord_height = m.chord_height;
    std::vector<CubicSpan> spans;
    const Status s = FitPolyline(d.points, d.tangents, options, &spans);
    if (!s.ok()) {
      std::printf("| %s | %s | failed: %s | | | | |\n", d.name.c_str(), m.name, s.message().c_str());
      continue;
    }
    const SpanErrors e = MeasureSpanErrors(d.points, spans, d.ideal, kSamplesPerSpan);
    std::printf("| %s | %s | %.3g | %.3g | %.0f | %.2g | %zu spans |\n", d.name.c_str(), m.name,
                1e3 * e.max_fit_error_mm, 1e3 * e.max_chord_error_mm,
                e.max_chord_error_mm / e.max_fit_error_mm, e.max_join_angle_deg, spans.size());
  }
}

void PrintLeastSquaresRow(const Dataset& d, Parametrization kind, const char* name) {
  LeastSquaresFitOptions options;
  options.parametrization = kind;
  options.tolerance_mm = 1e-3;
  LeastSquaresFit fit;
  const Status s = FitLeastSquares(d.points, options, &fit);
  if (!s.ok()) {
    std::printf("| %s | %s | failed: %s | | | | |\n", d.name.c_str(), name, s.message().c_str());
    return;
  }
  const auto& t = fit.parameters;
  double worst = 0.0;
  for (size_t i = 0; i + 1 < d.points.size(); ++i) {
    // Search the curve over the neighbouring data intervals.
    const double lo = t[i == 0 ? 0 : i - 1], hi = t[std::min(i + 2, t.size() - 1)];
    for (int k = 1; k <= kSamplesPerSpan; ++k) {
      const Eigen::Vector3d q = d.ideal(i, double(k) / (kSamplesPerSpan + 1));
      worst = std::max(worst, DistanceToCurve([&fit](double u) { return fit.curve.Point(u); },
                                              lo, hi, q));
    }
  }
  std::printf("| %s | %s | %.3g | | | 0 (C2) | %zu control points |\n", d.name.c_str(), name,
              1e3 * worst, fit.curve.control_points().size());
}

int Run(int argc, char** argv) {
  std::string surface = std::string(TPOPT_SOURCE_DIR) + "/data/pencil/surface_120x120x55.json";
  std::string curves = std::string(TPOPT_SOURCE_DIR) + "/data/pencil/flower_guides.json";
  if (argc > 1) {
    std::fprintf(stderr, "usage: parametrization_benchmark (no arguments)\n");
    return 2;
  }
  (void)argv;
  PencilJob job;
  std::vector<PencilRun> runs;
  Dataset pencil;
  Status s = LoadPencilJob(surface, curves, PencilOptions().ball_radius_mm, &job);
  if (s.ok()) s = Pencil(job, &runs, &pencil);
  if (!s.ok()) {
    std::fprintf(stderr, "parametrization_benchmark: %s\n", s.message().c_str());
    return 1;
  }
  std::printf("| CL data | method | max deviation from the ideal CL curve um | chord error of "
              "straight segments um | ratio | max tangent step at joins deg | pieces |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const Dataset& d : {Helix(), Ellipse(), pencil}) {
    PrintLocalRows(d);
    PrintLeastSquaresRow(d, Parametrization::kChordLength, "global least squares, chord, 1 um");
    PrintLeastSquaresRow(d, Parametrization::kApproximateArc,
                         "global least squares, approx. arc, 1 um");
  }
  return 0;
}

}  // namespace
}  // namespace tpopt

int main(int argc, char** argv) { return tpopt::Run(argc, argv); }
