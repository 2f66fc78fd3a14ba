// Every options struct's IsValid names the field, as the flag that sets it
// (or as the field where no flag does), and the value it got: one row a
// message, each against the whole text.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "model/machine/axis_metrics.h"
#include "model/cad/cad_io.h"
#include "model/eval/deviation.h"
#include "model/io/gcode_io.h"
#include "model/path/link_moves.h"
#include "model/path/path_generator.h"
#include "model/path/pencil_path.h"
#include "model/eval/random_cases.h"
#include "model/base/units.h"
#include "solver/fit/bspline_fit.h"
#include "solver/fit/bspline_least_squares.h"
#include "solver/smooth/ceres_smoother.h"
#include "solver/fit/curve_output.h"
#include "solver/smooth/feed_scheduler.h"
#include "solver/smooth/resample.h"
#include "solver/spline/spline_smoother.h"
#include "solver/strip/strip_path.h"
#include "solver/strip/tool_posture.h"

namespace tpopt {
namespace {

// Default options changed by `spoil` must be refused with exactly `message`;
// the defaults themselves must pass.
template <typename Options>
void ExpectRefused(const std::function<void(Options*)>& spoil, const std::string& message) {
  std::string why;
  ASSERT_TRUE(Options().IsValid(&why)) << why;
  Options o;
  spoil(&o);
  why.clear();
  EXPECT_FALSE(o.IsValid(&why)) << message;
  EXPECT_EQ(why, message);
}

template <typename Options>
struct Row {
  std::function<void(Options*)> spoil;
  std::string message;
};

template <typename Options>
void ExpectAll(const std::vector<Row<Options>>& rows) {
  for (const Row<Options>& row : rows) ExpectRefused<Options>(row.spoil, row.message);
}

TEST(OptionsValidationTest, HighAccuracyOptions) {
  using O = HighAccuracyOptions;
  ExpectAll<O>({
      {[](O* o) { o->tolerance_mm = 0; }, "--tolerance_mm must be finite and > 0 (got 0)"},
      {[](O* o) { o->overcut_factor = 0.5; }, "--overcut_factor must be finite and >= 1 (got 0.5)"},
      {[](O* o) { o->w_deviation = -1; }, "--w_deviation must be finite and >= 0 (got -1)"},
      {[](O* o) { o->w_second = NAN; }, "--w_second must be finite and >= 0 (got nan)"},
      {[](O* o) { o->w_third = -2; }, "--w_third must be finite and >= 0 (got -2)"},
      {[](O* o) { o->w_tip_second = -3; }, "--w_tip_second must be finite and >= 0 (got -3)"},
      {[](O* o) { o->w_tip_third = INFINITY; }, "--w_tip_third must be finite and >= 0 (got inf)"},
      {[](O* o) { o->w_limits = -4; }, "--w_limits must be finite and >= 0 (got -4)"},
      {[](O* o) { o->w_tip_height = -5; }, "--w_tip_height must be finite and >= 0 (got -5)"},
      {[](O* o) { o->w_tip_slide = NAN; }, "--w_tip_slide must be finite and >= 0 (got nan)"},
      {[](O* o) { o->w_walls = -6; }, "--w_walls must be finite and >= 0 (got -6)"},
      {[](O* o) { o->w_peak_second = -7; }, "--w_peak_second must be finite and >= 0 (got -7)"},
      {[](O* o) { o->peak_second_cap_per_mm2[1] = NAN; },
       "peak_second_cap_per_mm2[1] must be finite and >= 0 (got nan)"},
      {[](O* o) { o->ruling_departure_factor = -1; },
       "--ruling_departure_factor must be finite and >= 0 (got -1)"},
      {[](O* o) { o->end_of_cut_guard_weight = -0.5; },
       "--end_of_cut_guard_weight must be finite and >= 0 (got -0.5)"},
      {[](O* o) { o->axis_cone_deg = 91; }, "--axis_cone_deg must be in (0, 90] (got 91)"},
      {[](O* o) { o->travel_margin_mm = 0; }, "travel_margin_mm must be finite and > 0 (got 0)"},
      {[](O* o) { o->limit_margin = 1.5; }, "--limit_margin must be in (0, 1] (got 1.5)"},
      {[](O* o) { o->guard_distances_mm[2] = -1; },
       "guard_distances_mm[2] must be finite and > 0 (got -1)"},
      {[](O* o) { o->end_guard_distances_mm[0] = 0; },
       "end_guard_distances_mm[0] must be finite and > 0 (got 0)"},
      {[](O* o) { o->guard_distances_mm[3] = o->guard_distances_mm[1]; },
       "guard_distances_mm[3] must be distinct from those before it (got 0.6)"},
      {[](O* o) {
         o->end_guard_distances_mm = {0.15, 0.3};
       },
       "end_guard_distances_mm[1] must be distinct from those before it and from "
       "guard_distances_mm (got 0.3)"},
      {[](O* o) { o->between_min_move_mm = -0.1; },
       "between_min_move_mm must be finite and >= 0 (got -0.1)"},
      {[](O* o) { o->ruling_samples = 1; }, "--ruling_samples must be >= 2 (got 1)"},
      {[](O* o) { o->between_samples = -1; }, "--between_samples must be >= 0 (got -1)"},
      {[](O* o) { o->angle_tolerance_deg = 0; }, "--angle_tolerance_deg must be > 0 (got 0)"},
      {[](O* o) { o->w_band = 0; }, "w_band must be > 0 (got 0)"},
      {[](O* o) { o->slide_weight = -1; }, "slide_weight must be >= 0 (got -1)"},
      {[](O* o) { o->default_feed_mm_per_min = 0; }, "--feed must be > 0 mm/min (got 0)"},
      {[](O* o) { o->window_poses = 50; },
       "--window_poses must be 0 (no windows) or >= 100 (got 50)"},
      {[](O* o) { o->pole_window_path_poses = -1; },
       "--pole_window_path_poses must be >= 0 (got -1)"},
      {[](O* o) { o->coarse_poses = -1; }, "--coarse_poses must be >= 0 (got -1)"},
      {[](O* o) { o->refine_iterations = -1; }, "--refine_iterations must be >= 0 (got -1)"},
      {[](O* o) { o->pole_passage_deg = 90; }, "--pole_passage_deg must be in [0, 90) (got 90)"},
      {[](O* o) { o->max_iterations = -1; }, "--max_iterations must be >= 0 (got -1)"},
      {[](O* o) { o->num_threads = 0; }, "--num_threads must be >= 1 (got 0)"},
  });
}

TEST(OptionsValidationTest, SplineSmootherOptions) {
  using O = SplineSmootherOptions;
  ExpectAll<O>({
      {[](O* o) { o->zone_factor = 1; }, "--zone_factor must be finite and > 1 (got 1)"},
      {[](O* o) { o->zone_padding = -1; }, "--zone_padding must be >= 0 (got -1)"},
      {[](O* o) { o->angle_tolerance_deg = 0; },
       "--spline_tolerance_deg must be finite and > 0 (got 0)"},
      {[](O* o) { o->zone_weight = 2; }, "zone_weight must be in (0, 1] (got 2)"},
      {[](O* o) { o->pole_passage_deg = -1; }, "--pole_passage_deg must be in [0, 90) (got -1)"},
      {[](O* o) { o->pole_crossing_deg = -1; },
       "--pole_crossing_deg must be finite and >= 0 (got -1)"},
  });
}

TEST(OptionsValidationTest, FeedScheduleOptions) {
  using O = FeedScheduleOptions;
  ExpectAll<O>({
      {[](O* o) { o->margin = 1; }, "margin must be in (0, 1) (got 1)"},
      {[](O* o) { o->max_feed_step = 0; }, "--max_feed_step must be finite and > 0 (got 0)"},
      {[](O* o) { o->default_feed_mm_per_min = -1; },
       "--feed must be finite and > 0 mm/min (got -1)"},
      {[](O* o) { o->max_passes = 0; }, "max_passes must be >= 1 (got 0)"},
      {[](O* o) { o->max_feed_mm_per_min = 0; }, "--max_feed_mm_per_min must be > 0 (got 0)"},
      {[](O* o) { o->max_feed_factor = 0.5; },
       "--max_feed_factor must be finite and >= 1 (got 0.5)"},
  });
}

TEST(OptionsValidationTest, OutputAndFitOptions) {
  ExpectRefused<ResampleOptions>([](ResampleOptions* o) { o->step_mm = -1; },
                                 "--resample_step_mm must be finite and > 0 (got -1)");
  ExpectRefused<LocalFitOptions>([](LocalFitOptions* o) { o->chord_height_mm = -1; },
                                 "--fit_chord_height_mm must be finite and >= 0 (got -1)");
  ExpectRefused<LeastSquaresFitOptions>(
      [](LeastSquaresFitOptions* o) { o->tolerance_mm = 0; },
      "tolerance_mm must be finite and > 0 (got 0)");
  using C = CurveOutputOptions;
  ExpectAll<C>({
      {[](C* o) { o->fit.chord_height_mm = -2; },
       "--fit_chord_height_mm must be finite and >= 0 (got -2)"},
      {[](C* o) { o->sample_step_mm = 0; }, "--curve_step_mm must be finite and > 0 (got 0)"},
      {[](C* o) { o->corner_angle_deg = 181; }, "corner_angle_deg must be in (0, 180] (got 181)"},
  });
}

TEST(OptionsValidationTest, PostureAndStripPathOptions) {
  using P = PostureOptions;
  ExpectAll<P>({
      {[](P* o) { o->tolerance_mm = 11; }, "--tolerance_mm must be in (0, 10] (got 11)"},
      {[](P* o) { o->min_lead_rad = 0; }, "--min_lead_deg must be > 0 (got 0)"},
      {[](P* o) { o->max_lead_rad = 90 * kDegToRad; },
       "--max_lead_deg must be >= --min_lead_deg and < 90 (got 90)"},
      {[](P* o) {
         o->min_lead_rad = 1 * kDegToRad;
         o->max_lead_rad = 10 * kDegToRad;
         o->sturz_lead_rad = 20 * kDegToRad;
       },
       "--lead_deg must be in [--min_lead_deg, --max_lead_deg] = [1, 10] (got 20)"},
      {[](P* o) { o->max_tilt_rad = -1 * kDegToRad; }, "--max_tilt_deg must be in [0, 90) (got -1)"},
      {[](P* o) { o->gouge_tolerance_mm = -1; }, "gouge_tolerance_mm must be >= 0 (got -1)"},
      {[](P* o) { o->angle_resolution_rad = 0; }, "angle_resolution_rad must be > 0 (got 0)"},
      {[](P* o) { o->continuity_tie = 1; }, "continuity_tie must be in [0, 1) (got 1)"},
  });
  using S = StripPathOptions;
  ExpectAll<S>({
      {[](S* o) { o->posture.tolerance_mm = 0; }, "--tolerance_mm must be in (0, 10] (got 0)"},
      {[](S* o) { o->poses = 2; }, "--cc_points must be in [3, 100000] (got 2)"},
      {[](S* o) { o->path_v = 1.5; }, "--path_v must be in [0, 1] (got 1.5)"},
      {[](S* o) { o->u_begin = 0.6, o->u_end = 0.4; },
       "u range (u_begin, u_end) must satisfy 0 <= u_begin < u_end <= 1 (got [0.6, 0.4])"},
      {[](S* o) { o->samples_per_side = 5; }, "--section_samples must be in [10, 10000] (got 5)"},
  });
}

TEST(OptionsValidationTest, ModelOptions) {
  using F = FlankPathOptions;
  ExpectAll<F>({
      {[](F* o) { o->cutter_radius_mm = 0; }, "--cutter_radius must be finite and > 0 mm (got 0)"},
      {[](F* o) { o->poses = 1; }, "--poses must be >= 2 (got 1)"},
      {[](F* o) { o->feed_mm_per_min = 0; }, "--feed must be finite and > 0 mm/min (got 0)"},
      {[](F* o) { o->uv_distortion = 0.6; },
       "--uv_distortion must be finite and within [-0.5, 0.5] (got 0.6)"},
      {[](F* o) { o->distortion_width = 0; }, "--distortion_width must be in (0, 1] (got 0)"},
      {[](F* o) { o->distortion_center = -0.1; },
       "--distortion_center must be in [0, 1] (got -0.1)"},
      {[](F* o) { o->axis_noise_deg = 45; }, "--axis_noise_deg must be in [0, 45) (got 45)"},
      {[](F* o) { o->flute_length_mm = -1; }, "--flute_length must be finite and >= 0 mm (got -1)"},
      {[](F* o) { o->taper_rad = 1; }, "taper_rad must be in [0, pi/4) (got 1)"},
  });
  using D = DeviationOptions;
  ExpectAll<D>({
      {[](D* o) { o->samples_u = 1; }, "--samples_u must be >= 2 (got 1)"},
      {[](D* o) { o->samples_v = 0; }, "--samples_v must be >= 2 (got 0)"},
      {[](D* o) { o->substeps = 0; }, "substeps must be >= 1 (got 0)"},
      {[](D* o) { o->u_min = 0.5, o->u_max = 0.2; },
       "u range (u_min, u_max) must satisfy 0 <= u_min <= u_max <= 1, or both be NaN for the "
       "path's (got [0.5, 0.2])"},
  });
  ExpectRefused<MotionOptions>([](MotionOptions* o) { o->default_feed_mm_per_min = 0; },
                               "--feed must be finite and > 0 mm/min (got 0)");
  ExpectRefused<GcodeOptions>([](GcodeOptions* o) { o->default_feed_mm_per_min = NAN; },
                              "--feed must be finite and > 0 mm/min (got nan)");
  ExpectRefused<LinkMoveOptions>([](LinkMoveOptions* o) { o->feed_ratio = 0.5; },
                                 "--link_feed_ratio must be 0 (no links) or finite and > 1 (got 0.5)");
  using P = PencilOptions;
  ExpectAll<P>({
      {[](P* o) { o->ball_radius_mm = 0; }, "--ball_radius must be finite and > 0 mm (got 0)"},
      {[](P* o) { o->feed_mm_per_min = -1; }, "--feed must be finite and > 0 mm/min (got -1)"},
      {[](P* o) { o->interpolation_period_s = -0.002; },
       "--interpolation_period_ms must be finite and > 0 ms (got -2)"},
  });
  using R = RandomCaseOptions;
  ExpectAll<R>({
      {[](R* o) { o->poses = 3; }, "poses must be >= 4 (got 3)"},
      {[](R* o) { o->near_pole_fraction = 2; }, "near_pole_fraction must be in [0, 1] (got 2)"},
      {[](R* o) { o->feed_mm_per_min = 0; }, "feed_mm_per_min must be finite and > 0 (got 0)"},
  });
}


TEST(OptionsValidationTest, CadOptions) {
  if (!CadIoAvailable()) GTEST_SKIP() << "built without OpenCASCADE";
  using R = CadReadOptions;
  ExpectAll<R>({
      {[](R* o) { o->face_index = -2; }, "--face must be >= 0 (or -1: the only face) (got -2)"},
      {[](R* o) { o->ruling = "w"; }, "--ruling must be u or v (got 'w')"},
      {[](R* o) { o->max_ruled_deviation_mm = -1; },
       "--max_ruled_deviation_mm must be finite and >= 0 (got -1)"},
  });
  ExpectRefused<CadWriteOptions>([](CadWriteOptions* o) { o->length_unit = "FOOT"; },
                                 "length_unit must be MM or INCH (got 'FOOT')");
}

}  // namespace
}  // namespace tpopt
