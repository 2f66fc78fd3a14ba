// Every command-line flag of tpopt (only apps/ defines flags).
#ifndef TPOPT_APPS_FLAGS_H_
#define TPOPT_APPS_FLAGS_H_

#include <gflags/gflags.h>

// Inputs and outputs.
DECLARE_string(surface);
DECLARE_int32(face);
DECLARE_string(ruling);
DECLARE_bool(flip_cutter_side);
DECLARE_double(max_ruled_deviation_mm);
DECLARE_string(machine);
DECLARE_string(in);
DECLARE_string(out);
DECLARE_string(report);
DECLARE_bool(quiet);
DECLARE_double(progress_after_s);

// Pictures (evaluate and smooth).
DECLARE_string(html);
DECLARE_string(vtk);

// G-code (.ngc / .nc files)
DECLARE_string(gcode_style);
DECLARE_string(gcode_in_style);
DECLARE_bool(gcode_inverse_time);
DECLARE_string(gcode_preamble);
DECLARE_string(gcode_postamble);

// Cutter (overrides what the path file says).
DECLARE_double(cutter_radius);
DECLARE_double(flute_length);

// generate
DECLARE_int32(poses);
DECLARE_string(strategy);
DECLARE_double(uv_distortion);
DECLARE_double(distortion_center);
DECLARE_double(distortion_width);
DECLARE_double(axis_noise_deg);
DECLARE_int32(noise_seed);
DECLARE_double(feed);

// evaluate
DECLARE_int32(samples_u);
DECLARE_int32(samples_v);
DECLARE_bool(whole_surface);
DECLARE_bool(judge_on_input_range);
DECLARE_bool(even_stations);
DECLARE_int32(split_moves_for_tolerance);
DECLARE_string(interpolation);



// smooth
DECLARE_string(mode);
DECLARE_double(tolerance_mm);
DECLARE_double(spline_tolerance_deg);
DECLARE_double(overcut_factor);
DECLARE_double(w_deviation);
DECLARE_double(w_second);
DECLARE_double(w_third);
DECLARE_double(ruling_departure_factor);
DECLARE_double(end_of_cut_guard_weight);
DECLARE_double(w_tip_second);
DECLARE_double(w_tip_third);
DECLARE_double(w_limits);
DECLARE_double(limit_margin);
DECLARE_double(w_tip_height);
DECLARE_double(w_tip_slide);
DECLARE_double(w_peak_second);
DECLARE_double(axis_cone_deg);
DECLARE_double(w_walls);
DECLARE_int32(ruling_samples);
DECLARE_int32(between_samples);
DECLARE_int32(max_iterations);
DECLARE_int32(coarse_poses);
DECLARE_int32(refine_iterations);
DECLARE_double(pole_passage_deg);
DECLARE_int32(pole_window_path_poses);
DECLARE_double(pole_crossing_deg);
DECLARE_int32(window_poses);
DECLARE_int32(num_threads);
DECLARE_double(angle_tolerance_deg);
DECLARE_double(zone_factor);
DECLARE_int32(zone_padding);
DECLARE_bool(insert_transitions);
DECLARE_bool(smooth_outside_zones);
DECLARE_bool(accept_over_tolerance);
DECLARE_bool(keep_runs_no_worse);
DECLARE_double(stiffer_above_flank_d2);
DECLARE_double(peak_d2_cap_over_flank);
DECLARE_int32(stiffer_solves);
DECLARE_int32(peak_deviation_rounds);
DECLARE_double(link_feed_ratio);
DECLARE_bool(schedule_feed);
DECLARE_string(feed_mode);
DECLARE_string(cnc_summary);
DECLARE_double(max_feed_mm_per_min);
DECLARE_double(max_feed_factor);
DECLARE_bool(raise_within_input_peaks);
DECLARE_double(keep_run_time_window_mm);
DECLARE_double(max_feed_step);
DECLARE_double(resample_step_mm);
// stripwidth
DECLARE_string(method);
DECLARE_string(cutter);
DECLARE_int32(cc_points);
DECLARE_double(path_v);
DECLARE_double(lead_deg);
DECLARE_double(min_lead_deg);
DECLARE_double(max_lead_deg);
DECLARE_double(max_tilt_deg);
DECLARE_int32(section_samples);

// Cubic B-spline curve output (smooth, pencil)
DECLARE_string(output_curve);
DECLARE_double(curve_step_mm);
DECLARE_string(fit_parametrization);
DECLARE_string(fit_chord_height);
DECLARE_double(fit_chord_height_mm);

// pencil
DECLARE_string(curve);
DECLARE_double(ball_radius);
DECLARE_double(interpolation_period_ms);

// The part on the table (APT programs)
DECLARE_string(part_setup);
// LinuxCNC tool table (G-code programs)
DECLARE_string(tool_table);
#endif  // TPOPT_APPS_FLAGS_H_
