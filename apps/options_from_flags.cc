#include "apps/options_from_flags.h"

#include <cstdlib>

#include <gflags/gflags.h>

#include "apps/flags.h"
#include "model/base/units.h"

namespace tpopt {

Status MetricOptionsFromFlags(DeviationOptions* deviation, MotionOptions* motion) {
  deviation->samples_u = FLAGS_samples_u;
  deviation->samples_v = FLAGS_samples_v;
  if (FLAGS_whole_surface) {
    deviation->u_min = 0.0;
    deviation->u_max = 1.0;
  }
  motion->default_feed_mm_per_min = FLAGS_feed;
  std::string why;
  if (!deviation->IsValid(&why) || !motion->IsValid(&why)) return Status::Usage(why);
  return Status::Ok();
}

Status FeedScheduleOptionsFromFlags(FeedScheduleOptions* feed) {
  feed->default_feed_mm_per_min = FLAGS_feed;
  if (FLAGS_feed_mode != "lower" && FLAGS_feed_mode != "raise" &&
      FLAGS_feed_mode != "keep_run_time") {
    return Status::Usage("--feed_mode=" + FLAGS_feed_mode +
                         " must be lower, raise or keep_run_time");
  }
  feed->mode = FLAGS_feed_mode == "raise"           ? FeedMode::kRaise
               : FLAGS_feed_mode == "keep_run_time" ? FeedMode::kKeepRunTime
                                                    : FeedMode::kLower;
  feed->keep_input_peaks = FLAGS_raise_within_input_peaks;
  feed->keep_run_time_window_mm = FLAGS_keep_run_time_window_mm;
  if (FLAGS_max_feed_mm_per_min != 0.0) feed->max_feed_mm_per_min = FLAGS_max_feed_mm_per_min;
  feed->max_feed_factor = FLAGS_max_feed_factor;
  feed->max_feed_step = FLAGS_max_feed_step;
  std::string why;
  if (!feed->IsValid(&why)) return Status::Usage(why);
  return Status::Ok();
}

Status LinkMoveOptionsFromFlags(LinkMoveOptions* links) {
  links->feed_ratio = FLAGS_link_feed_ratio;
  std::string why;
  if (!links->IsValid(&why)) return Status::Usage(why);
  return Status::Ok();
}

namespace {

// `flag_value` unless the flag was left at its default, then `fallback`.
double UnlessDefault(const char* flag, double flag_value, double fallback) {
  return gflags::GetCommandLineFlagInfoOrDie(flag).is_default ? fallback : flag_value;
}

}  // namespace

Status SmootherOptionsFromFlags(bool surface_free, SplineSmootherOptions* spline,
                                HighAccuracyOptions* ha) {
  spline->angle_tolerance_deg = FLAGS_spline_tolerance_deg;
  spline->zone_factor = FLAGS_zone_factor;
  spline->zone_padding = FLAGS_zone_padding;
  spline->insert_transitions = FLAGS_insert_transitions;
  spline->smooth_outside_zones = FLAGS_smooth_outside_zones;
  spline->pole_passage_deg = FLAGS_pole_passage_deg;
  spline->pole_crossing_deg = FLAGS_pole_crossing_deg;
  ha->tolerance_mm = FLAGS_tolerance_mm;
  ha->overcut_factor = FLAGS_overcut_factor;
  ha->w_deviation = FLAGS_w_deviation;
  ha->w_second = FLAGS_w_second;
  ha->w_third = FLAGS_w_third;
  ha->ruling_departure_factor = FLAGS_ruling_departure_factor;
  ha->end_of_cut_guard_weight = FLAGS_end_of_cut_guard_weight;
  ha->w_tip_second = FLAGS_w_tip_second;
  ha->w_tip_third = FLAGS_w_tip_third;
  ha->w_limits = FLAGS_w_limits;
  ha->limit_margin = FLAGS_limit_margin;
  ha->w_tip_height = FLAGS_w_tip_height;
  ha->w_tip_slide = FLAGS_w_tip_slide;
  ha->w_peak_second = FLAGS_w_peak_second;
  ha->axis_cone_deg = FLAGS_axis_cone_deg;
  ha->w_walls = FLAGS_w_walls;
  ha->ruling_samples = FLAGS_ruling_samples;
  ha->between_samples = FLAGS_between_samples;
  ha->max_iterations = FLAGS_max_iterations;
  ha->coarse_poses = FLAGS_coarse_poses;
  ha->refine_iterations = FLAGS_refine_iterations;
  ha->window_poses = FLAGS_window_poses;
  ha->pole_passage_deg = FLAGS_pole_passage_deg;
  ha->pole_window_path_poses = FLAGS_pole_window_path_poses;
  ha->num_threads = FLAGS_num_threads;
  ha->default_feed_mm_per_min = FLAGS_feed;
  ha->angle_tolerance_deg = FLAGS_angle_tolerance_deg;
  if (surface_free) {
    const HighAccuracyOptions defaults = HighAccuracyOptions::SurfaceFree();
    ha->w_second = UnlessDefault("w_second", FLAGS_w_second, defaults.w_second);
    ha->w_third = UnlessDefault("w_third", FLAGS_w_third, defaults.w_third);
    ha->w_tip_second = UnlessDefault("w_tip_second", FLAGS_w_tip_second, defaults.w_tip_second);
  }
  std::string why;
  if (!spline->IsValid(&why)) return Status::Usage(why);
  if (!ha->IsValid(&why)) return Status::Usage(why);
  return Status::Ok();
}

Status CurveOutputOptionsFromFlags(bool* bspline, CurveOutputOptions* options) {
  if (FLAGS_output_curve != "points" && FLAGS_output_curve != "bspline") {
    return Status::Usage("--output_curve=" + FLAGS_output_curve + " must be points or bspline");
  }
  *bspline = FLAGS_output_curve == "bspline";
  const std::string& p = FLAGS_fit_parametrization;
  if (p == "approximate_arc") {
    options->fit.parametrization = Parametrization::kApproximateArc;
  } else if (p == "chord") {
    options->fit.parametrization = Parametrization::kChordLength;
  } else if (p == "centripetal") {
    options->fit.parametrization = Parametrization::kCentripetal;
  } else if (p == "uniform") {
    options->fit.parametrization = Parametrization::kUniform;
  } else {
    return Status::Usage("--fit_parametrization=" + p +
                         " must be approximate_arc, chord, centripetal or uniform");
  }
  if (FLAGS_fit_chord_height != "fixed" && FLAGS_fit_chord_height != "neighbours") {
    return Status::Usage("--fit_chord_height=" + FLAGS_fit_chord_height +
                         " must be fixed or neighbours");
  }
  options->fit.chord_height =
      FLAGS_fit_chord_height == "fixed" ? ChordHeight::kFixed : ChordHeight::kFromNeighbours;
  options->fit.chord_height_mm = FLAGS_fit_chord_height_mm;
  options->sample_step_mm = FLAGS_curve_step_mm;
  std::string why;
  if (!options->IsValid(&why)) return Status::Usage(why);
  return Status::Ok();
}

Status FlankPathOptionsFromFlags(FlankPathOptions* options) {
  if (FLAGS_strategy == "spo") {
    options->strategy = FlankStrategy::kSinglePointOffset;
  } else if (FLAGS_strategy == "dpo") {
    options->strategy = FlankStrategy::kDoublePointOffset;
  } else {
    return Status::Usage("--strategy=" + FLAGS_strategy + " must be spo or dpo");
  }
  if (FLAGS_cutter_radius == 0.0) return Status::Usage("--cutter_radius is required");
  options->cutter_radius_mm = FLAGS_cutter_radius;
  options->poses = FLAGS_poses;
  options->feed_mm_per_min = FLAGS_feed;
  options->uv_distortion = FLAGS_uv_distortion;
  options->distortion_center = FLAGS_distortion_center;
  options->distortion_width = FLAGS_distortion_width;
  options->axis_noise_deg = FLAGS_axis_noise_deg;
  options->noise_seed = static_cast<unsigned>(FLAGS_noise_seed);
  options->flute_length_mm = FLAGS_flute_length;
  std::string why;
  if (!options->IsValid(&why)) return Status::Usage(why);
  return Status::Ok();
}

Status PencilOptionsFromFlags(PencilOptions* pencil) {
  pencil->ball_radius_mm = FLAGS_ball_radius;
  pencil->feed_mm_per_min = FLAGS_feed;
  pencil->interpolation_period_s = FLAGS_interpolation_period_ms / 1000.0;
  std::string why;
  if (!pencil->IsValid(&why)) return Status::Usage(why);
  return Status::Ok();
}

namespace {

// "torus:R,r" in mm.
Status ParseTorusFlag(const std::string& text, TorusCutter* cutter) {
  const std::string prefix = "torus:";
  const std::string usage = "--cutter=" + text + " must be torus:R,r (mm), e.g. torus:8,2";
  if (text.compare(0, prefix.size(), prefix) != 0) return Status::Usage(usage);
  const char* begin = text.c_str() + prefix.size();
  char* end = nullptr;
  cutter->radius_mm = std::strtod(begin, &end);
  if (end == begin || *end != ',') return Status::Usage(usage);
  const char* second = end + 1;
  cutter->corner_radius_mm = std::strtod(second, &end);
  if (end == second || *end != '\0') return Status::Usage(usage);
  std::string why;
  if (!cutter->IsValid(&why)) return Status::Usage("--cutter: " + why);
  return Status::Ok();
}

Status MethodFromFlag(const std::string& name, PostureMethod* method) {
  if (name == "sturz") {
    *method = PostureMethod::kSturz;
  } else if (name == "mpm") {
    *method = PostureMethod::kMultiPoint;
  } else if (name == "mpec") {
    *method = PostureMethod::kMidPointErrorControl;
  } else {
    return Status::Usage("--method=" + name + " must be sturz, mpm or mpec");
  }
  return Status::Ok();
}

}  // namespace

Status StripPathOptionsFromFlags(TorusCutter* cutter, StripPathOptions* options) {
  RETURN_IF_ERROR(ParseTorusFlag(FLAGS_cutter, cutter));
  RETURN_IF_ERROR(MethodFromFlag(FLAGS_method, &options->method));
  PostureOptions& posture = options->posture;
  posture.tolerance_mm = FLAGS_tolerance_mm;
  posture.sturz_lead_rad = FLAGS_lead_deg * kDegToRad;
  posture.min_lead_rad = FLAGS_min_lead_deg * kDegToRad;
  posture.max_lead_rad = FLAGS_max_lead_deg * kDegToRad;
  posture.max_tilt_rad = FLAGS_max_tilt_deg * kDegToRad;
  options->poses = FLAGS_cc_points;
  options->path_v = FLAGS_path_v;
  options->samples_per_side = FLAGS_section_samples;
  std::string why;
  if (!options->IsValid(&why)) return Status::Usage(why);
  if (!(FLAGS_feed > 0.0)) return Status::Usage("--feed must be > 0");
  return Status::Ok();
}

}  // namespace tpopt
