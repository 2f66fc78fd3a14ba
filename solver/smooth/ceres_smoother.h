// High-accuracy mode: the tool path as a nonlinear least-squares problem.
//
// Variables: per pose [A, C, p_w_tip] (solver/smooth/cost/pose_parameters.h). Each pose
// is tied to the surface parameter u_i of its contact ruling, found by
// projecting the *input* CL pose onto rail 0 (model/path/rail_projection.h).
// Residual families, each a functor with its formula in its header:
//   deviation   solver/smooth/cost/deviation_cost.h     swept cutter vs ruled surface
//   tip height  solver/smooth/cost/tip_height_cost.h    removes the slide along the axis
//   tip slide   solver/smooth/cost/tip_slide_cost.h     the slide along the path (w_tip_slide > 0)
//   tolerance   solver/smooth/cost/tolerance_band_cost.h  (surface-free, replaces both)
//   second      solver/smooth/cost/smoothness_cost.h    d2/ds2 of A, C and the tip
//   third       solver/smooth/cost/smoothness_cost.h    d3/ds3 of A, C and the tip
//   limits      solver/smooth/cost/axis_limit_cost.h    axis velocity/acceleration/jerk
//   walls       solver/smooth/cost/wall_cost.h          travel, axis cone, cutter's side
// Every family is scaled as an integral over the arc length s of the contact
// curve (rail 0 at u_i) divided by its length, so a weight means the same at
// any point density. The costs of one pose alone (its deviation at the
// pose, walls, tip height) share one residual block a pose
// (solver/smooth/cost/stacked_cost.h); the reports still split them by family.
#ifndef TPOPT_SOLVER_CERES_SMOOTHER_H_
#define TPOPT_SOLVER_CERES_SMOOTHER_H_

#include <ceres/ceres.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "model/base/status.h"
#include "model/cutter/cutter.h"
#include "model/geometry/ruled_surface.h"
#include "model/machine/interpolation.h"
#include "model/machine/machine.h"
#include "model/path/tool_path.h"
#include "solver/smooth/cost/stacked_cost.h"

namespace tpopt {

struct HighAccuracyOptions {
  // Deviation the cost is measured in, mm. > 0.
  double tolerance_mm = 0.01;
  // Overcut counts this many times more than undercut. >= 1.
  double overcut_factor = 3.0;
  // Weight of the deviation family (dimensionless).
  double w_deviation = 1.0;
  // Weights of the second/third derivative of A and C over arc length,
  // mm^4/rad^2 and mm^6/rad^2 (see smoothness_cost.h).
  double w_second = 300;
  double w_third = 3000;
  // With a surface, where every pose of a stencil has its ruling's angles
  // (solver/smooth/ruling_angles.h), the second and third derivatives are
  // of A's and C's departure from those angles, weighted this many times
  // w_second and w_third: the rulings' own turning is the surface's and
  // costs nothing, so the departure can be held far stiffer than the
  // angles without pulling the axis off the surface. 0 differentiates the
  // angles themselves everywhere. >= 0.
  double ruling_departure_factor = 100.0;
  // Near the pole (within kRulingAnglesPoleDeg, solver/smooth/ruling_angles.h)
  // A's departure from its ruling's A is differentiated too, where the
  // ruling clears the pole by kRulingAPoleClearance. Off in a first solve:
  // a run held to the tolerance by it can miss it (random seed 120 then
  // goes back as programmed); the pipeline's stiffer solves set it.
  bool ruling_a_near_pole = false;
  // A cap on each rotary axis's |d2/ds2| over the tip's travel, rad/mm^2
  // (solver/smooth/cost/peak_second_cost.h; 0: none for that axis), and
  // its weight (dimensionless): zero below the cap, so it bends the peaks
  // alone. The pipeline sets the caps from the surface's own flank path.
  std::array<double, 2> peak_second_cap_per_mm2 = {0.0, 0.0};
  double w_peak_second = 1e3;
  // Weights of the second/third derivative of the tip, mm^2 and mm^4.
  double w_tip_second = 1e-2;
  double w_tip_third = 0.0;
  // Weight of the axis-limit penalties (dimensionless, one-sided).
  double w_limits = 0.0;
  // The limit penalties start at this fraction of each limit. (0, 1].
  double limit_margin = 0.95;
  // Weight of the tip-height gauge (dimensionless), which holds each tip
  // where the input had it along the axis relative to the floor (rail 0).
  double w_tip_height = 1.0;
  // Weight of holding each tip where the solve starts it along the path
  // (solver/smooth/cost/tip_slide_cost.h), dimensionless; 0: the tips slide
  // freely along it. Where it is 0, the pipeline's stiffer steps set it
  // from the first step refused from both starts on (SolveStiffer).
  double w_tip_slide = 0.0;
  // With a surface, each axis stays within this half angle of the input's
  // axis (solver/smooth/cost/axis_cone_cost.h): wide enough for the smoothing (which
  // turns axes by a degree or two) and for 0.5 deg of CAM noise, narrow
  // enough that no axis swings round its contact line. Degrees, (0, 90].
  double axis_cone_deg = 12.0;
  // Weight of the walls that keep each axis in its cone and on its side of
  // the surface (solver/smooth/cost/surface_side_cost.h), and each linear joint inside
  // its travel less travel_margin_mm (solver/smooth/cost/travel_cost.h). Dimensionless;
  // 0 turns them off.
  double w_walls = 1e4;
  double travel_margin_mm = 0.5;
  // Sample points along each ruling for the deviation family. >= 2.
  int ruling_samples = 7;
  // Distances (mm along rail 0) of the guard rulings on each side of a
  // pose's own, which its cutter must not cut into (deviation_cost.h).
  std::vector<double> guard_distances_mm = {0.3, 0.6, 1.2, 2.4};
  // Distances (mm) of guard rulings held at their ends only (v = 0 and 1).
  // The contact family sees only each cutter's own ruling, so an axis
  // turned a little about the surface normal costs it nothing, while its
  // cutter cuts the rulings a tenth or two of a millimetre away by
  // micrometres at their ends. A guard at the middle as well pushes the
  // cutter of a strongly twisted surface off its ruling instead (README,
  // "Random cases", stop 30). A cylinder of radius R held on a ruling whose
  // normal turns by theta from its contact to an end cuts deepest into the
  // rulings about theta R away, so a thin cutter on a mild twist needs
  // guards nearer than 0.15 mm (seed 115, R 2 mm: 2.9 x the clean DPO
  // path's max |dev| with 0.15 alone, 0.2 x with these; stop 41).
  std::vector<double> end_guard_distances_mm = {0.04, 0.08, 0.15};
  // A point held to the tolerance is a guard at the middle of each move
  // between two poses within the guard distances of it; with a spacing > 0,
  // at points at most this far apart (mm of contact arc length) inside
  // every move with one such pose at an end. The cutter that gouges a point
  // near a surface's end or across a strong twist does so inside the move
  // that starts at its ruling, away from both poses (issue 16, seed 36:
  // 0.0355 mm at any weight). More residuals on long moves, slower rounds:
  // the pipeline asks for them only after a solve without them broke the
  // tolerance. >= 0.
  double held_point_guard_spacing_mm = 0.0;
  // Under joint interpolation, the weight of the guards inside the two moves
  // either side of a cut's end pose, relative to the held point's own
  // (solver/smooth/ceres_smoother.cc, AddTolerancePoints). At the point's
  // full weight the first solve of random cases 29 and 64 came out rougher
  // and the stiffer steps did not bring it back; at a hundredth the floor
  // corner they are there for stays held (case 173), and more cases meet
  // the targets (README, "Random cases", stops 49 and 50). >= 0.
  double end_of_cut_guard_weight = 0.01;
  // Points inside each move (at the controller's interpolation) checked
  // for deviation (0 = poses only). On 200 random cases (README, "Random
  // cases", stop 28) two hold more of them within the clean DPO path's
  // max |dev| and 2 x the clean SPO path's d2 than one (126 against 119),
  // three or five no more than two.
  int between_samples = 2;
  // Moves shorter than this (mm of contact arc length) get no between
  // samples: on them the joint-linear motion stays within a fraction of a
  // micrometre of the two end poses' cutters, which are checked, and a
  // dense path would pay for the between points for nothing. >= 0.
  double between_min_move_mm = 0.1;
  // The controller's motion the between points follow (model/
  // interpolation.h). RunSmoothing sets it to its DeviationOptions', so that
  // the cost and the judge of the result agree.
  Interpolation interpolation = Interpolation::kJoint;
  // Surface-free mode (no surface): each pose stays within tolerance_mm of
  // the original tip polyline and within this angle of the original axis
  // (solver/smooth/cost/tolerance_band_cost.h); the band's walls weigh w_band, and
  // slide_weight keeps poses at their stations along the path.
  double angle_tolerance_deg = 0.5;
  double w_band = 1e4;
  double slide_weight = 0.1;
  // Programmed feed where the path has none, mm/min. > 0.
  double default_feed_mm_per_min = 1000.0;
  int max_iterations = 100;
  // With a surface, paths with more than twice this many poses are solved
  // coarse to fine (solver/smooth/coarse_to_fine.h): first over every 8th pose
  // (recursively, down to about this many stations), then each finer level
  // from the interpolated stations for at most refine_iterations. 0 always
  // solves the full problem directly.
  int coarse_poses = 250;
  int refine_iterations = 5;
  // Longer problems are solved in overlapping windows of this many poses
  // (solver/smooth/windowed_solve.h), which bounds the memory. 0 = never; else
  // >= 100.
  int window_poses = 20000;
  // With a surface, every stretch of the initial guess whose axis stays
  // within this angle of the pole (A = 0) while C turns by a quarter turn or
  // more is also solved the other way round the pole, and the cheaper
  // solution kept (solver/smooth/both_ways_round_poles.h). Degrees, [0, 90); 0 = never.
  double pole_passage_deg = 5.0;
  // On a path of more poses than this, each passage is tried the other way
  // in a window round it, not by solving the whole path again, so that its
  // cost does not grow with the path (0 = always the whole path). A window
  // takes two solves of a few hundred poses where the whole path takes one,
  // so a window pays only on a long path (README, "Figures behind the
  // defaults").
  int pole_window_path_poses = 5000;
  // Ceres' relative cost-change stop.
  double function_tolerance = 1e-6;
  // Jacobian evaluation threads. Runs with the same count give the same
  // result (tested); a different count may differ in the last digits.
  int num_threads = 2;
  // Called after each Ceres iteration with its number and cost (for a
  // progress display); may be empty. Each iteration is also logged at glog
  // verbosity 1 (`-v=1`).
  std::function<void(int iteration, double cost)> on_iteration;

  bool IsValid(std::string* why) const;

  // The defaults for a run without a surface (data/presets/surface_free.flags):
  // there the band holds the accuracy, so the axes are smoothed as hard as
  // it allows (w_second 1e6) and the tip and third-derivative terms, which
  // only fight the band's walls, are off. With the surface defaults above,
  // the solve of LinuxCNC's impeller program ends worse than its start.
  static HighAccuracyOptions SurfaceFree();
};

// With a surface, how far a lead-in or lead-out pose beyond the surface's
// ends may leave its programmed line, mm (the solve's band, and the
// lead continuation's, solver/smooth/lead_continuation.h).
constexpr double kLeadBandMm = 1.0;

// A surface point the solve must bring within its bound, the tolerance or
// a lower one: one of the active set of grid points where a solve left the
// surface farther from the cutter than the tolerance, or than a round
// lowering the peak deviation asks (solver/smooth/smoothing_pipeline.cc). Its
// residual is the deviation family's at that one point, on the move whose
// contact rulings bracket u, with weight w_deviation * weight, measured in
// units of the bound with a dead band of 0.8 bound (deviation_cost.h): only
// its excess over that counts, and at one bound of excess it costs what the
// whole path does at one tolerance, times weight (dimensionless).
struct TolerancePoint {
  double u = 0.0, v = 0.0;  // surface parameters
  double weight = 1.0;
  // The bound where below the tolerance, mm (> 0).
  double bound_mm = INFINITY;
};

// What the problem is built from. All pointers are non-null except that the
// initial guess defaults to the input when absent, and that without a
// surface the problem is surface-free: the deviation and tip-height
// families give way to the tolerance band around the original program.
struct SmoothingInputs {
  const ToolPath* input = nullptr;          // the CAM path (gives u_i, feeds)
  const ToolPath* initial_guess = nullptr;  // same pose count as input
  const RuledSurface* surface = nullptr;
  const Cutter* cutter = nullptr;
  const Machine* machine = nullptr;
  // Poses held at the initial guess at the start and at the end (the seams
  // of a window, solver/smooth/windowed_solve.h).
  size_t held_first = 0;
  size_t held_last = 0;
  // With a surface, points held to the tolerance besides the deviation
  // family (may be null or empty).
  const std::vector<TolerancePoint>* tolerance_points = nullptr;
};

// Variables and bookkeeping of a built problem.
struct SmoothingState {
  std::vector<std::array<double, 5>> poses;  // [A, C, x, y, z] per pose
  std::vector<double> u;                     // contact ruling per pose
  // Poses of a lead-in or lead-out beyond the surface's ends
  // (PosesBeyondRailEnds; none without a surface): they start where the
  // program has them and are held by the smoothness and the walls, not tied
  // to the end ruling they do not touch.
  std::vector<bool> beyond_ends;
  std::vector<double> s_mm;                  // arc length of the contact on rail 0
  std::vector<double> t_s;                   // planned time at programmed feed
  // Residual blocks of each family, for per-family cost reports.
  std::map<std::string, std::vector<ceres::ResidualBlockId>> families;
  // The costs of one pose alone (its deviation at the pose, walls, tip
  // gauge), per pose, made one residual block a pose when the problem is
  // complete (solver/smooth/cost/stacked_cost.h), when Ceres takes them
  // over.
  struct PosePart {
    std::string family;
    std::unique_ptr<ceres::CostFunction> cost;
  };
  std::vector<std::vector<PosePart>> pose_parts;
  // Where each family's parts ended up in those blocks, for the reports.
  struct StackedPart {
    std::string family;
    const StackedCost* block;
    size_t part;
    size_t pose;
  };
  std::vector<StackedPart> stacked_parts;
};

struct HighAccuracyReport {
  bool converged = false;  // Ceres reported a usable solution
  std::string message;     // Ceres' termination message
  int iterations = 0;
  double solve_time_s = 0.0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  std::map<std::string, double> final_cost_by_family;
  // Surface-free: poses the solve left outside the band, moved back onto
  // its edge.
  int poses_clamped = 0;
  // Pole passages of the initial guess solved both ways round, and how many
  // of them the kept solution takes the other way (solver/smooth/both_ways_round_poles.h).
  int pole_passages = 0;
  int pole_passages_rerouted = 0;
  int pole_passages_in_windows = 0;  // tried in a window round them
};

// Fills `state` and adds every residual block to `problem`.
Status BuildProblem(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                    SmoothingState* state, ceres::Problem* problem);

// One Ceres solve of the whole problem as given: no repeated poses, no
// coarse levels, no windows. Writes the optimised path to `out`.
Status SolveWholeProblem(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                         ToolPath* out, HighAccuracyReport* report);

// Builds, solves and writes the optimised path (same poses, feeds and
// rapids as the input) to `out`: over the distinct poses, coarse to fine
// when the path is dense, in windows when it is long. Fails on bad input;
// a Ceres failure is reported through `report->converged`.
Status SmoothHighAccuracy(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                          ToolPath* out, HighAccuracyReport* report);

// The Ceres Solver version tpopt is built with, e.g. "2.1.0" (for reports;
// only solver/smooth/ includes Ceres).
std::string CeresVersion();

}  // namespace tpopt

#endif  // TPOPT_SOLVER_CERES_SMOOTHER_H_
