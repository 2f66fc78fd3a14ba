#include "apps/flags.h"

#include "model/path/link_moves.h"
#include "model/path/path_generator.h"
#include "model/path/pencil_path.h"
#include "solver/fit/curve_output.h"
#include "solver/smooth/smoothing_pipeline.h"
#include "solver/strip/strip_path.h"

namespace {

// A flag that sets an option to the option's own default takes it from
// the option, so the two cannot drift apart; the other literals below are
// in other units (deg for rad, ms for s) or the command line's own choice.
// (Defined before the flags: a translation unit initialises in order.)
const tpopt::SmoothingSettings kSettings;
const tpopt::LinkMoveOptions kLinks;
const tpopt::FlankPathOptions kFlankPath;
const tpopt::PencilOptions kPencil;
const tpopt::CurveOutputOptions kCurveOutput;
const tpopt::StripPathOptions kStripPath;

}  // namespace

DEFINE_string(surface, "",
              "The surface: tpopt's JSON (docs/ARCHITECTURE.md), or a face of a STEP (.stp, .step) or "
              "IGES (.igs, .iges) file.");
DEFINE_int32(face, -1,
             "STEP/IGES --surface: the face to read, 0-based (-1: the file must hold one face; "
             "otherwise the error lists them).");
DEFINE_string(ruling, "",
              "STEP/IGES --surface: the face parameter (u or v) along the ruling; empty detects "
              "it (the direction of degree 1, else the one closer to ruled).");
DEFINE_bool(flip_cutter_side, false,
            "STEP/IGES --surface: put the cutter on the side opposite the face's outward normal.");
DEFINE_double(max_ruled_deviation_mm, 0.01,
              "STEP/IGES --surface: refuse a face that is not exactly ruled when it lies farther "
              "than this from the ruled surface between its boundary curves, mm.");
DEFINE_string(machine, "",
              "Machine JSON (xyzac-trt kinematics and axis limits), or a LinuxCNC INI "
              "(*.ini, xyzac-trt-kins: its joint/axis limits and kinematics pins).");
DEFINE_string(in, "", "Input tool path: APT CL (.cls, .apt, .cl) or LinuxCNC G-code (.ngc, .nc).");
DEFINE_string(out, "",
              "Output tool path, APT or G-code by its extension; written whole or not at all.");
DEFINE_string(gcode_style, "tcp",
              "G-code output: tcp (X Y Z = tool tip in the workpiece, A C joints; the "
              "controller's TCP mode) or joint (X Y Z = machine joints by inverse kinematics).");
DEFINE_string(gcode_in_style, "tcp",
              "G-code input: the style (tcp or joint) at the start of the program; M428 and M429 "
              "in the program switch it.");
DEFINE_bool(gcode_inverse_time, false, "G-code output: G93 inverse-time feeds from the planned "
            "segment times instead of G94 mm/min.");
DEFINE_string(gcode_preamble, "(switch the controller to tool-centre-point mode here, e.g. M428)",
              "G-code output: line(s) before the first move, e.g. M428 or TRAORI.");
DEFINE_string(gcode_postamble, "", "G-code output: line(s) after the last move.");
DEFINE_string(report, "", "Report JSON to write (metrics of the input and output).");
DEFINE_bool(quiet, false, "No progress display, summary or reader warnings.");
DEFINE_double(progress_after_s, 1.0,
              "Seconds before the progress display appears on stderr (shorter runs show "
              "none); --quiet turns it off.");
DEFINE_string(html, "",
              "evaluate/smooth: write a self-contained HTML report (inline SVG plots of A and C "
              "against path length, the deviation map, the summary) to this file.");
DEFINE_string(vtk, "",
              "evaluate/smooth: write the surface with its deviation, the tool axes and the tip "
              "path for ParaView: .vtp (VTK XML PolyData) or .vtk (legacy), ASCII.");

DEFINE_double(cutter_radius, 0.0,
              "Cutter radius, mm. generate: required. evaluate/smooth: overrides the "
              "path file's TLDATA/CUTTER (0 = use the file's).");
DEFINE_double(flute_length, 0.0,
              "Cutter flute length, mm (0 = the path file's, else 1.25 x the longest ruling).");

DEFINE_int32(poses, kFlankPath.poses, "generate: number of poses along the surface.");
DEFINE_string(strategy, "spo", "generate: spo (single-point offset) or dpo (double-point offset).");
DEFINE_double(uv_distortion, kFlankPath.uv_distortion,
              "generate: amplitude (in u) of a CAM-like U/V mismatch bump pairing C1(u) with "
              "C2(u + delta(u)); 0 = a clean path.");
DEFINE_double(distortion_center, kFlankPath.distortion_center,
              "generate: u at the centre of the distortion bump.");
DEFINE_double(distortion_width, kFlankPath.distortion_width,
              "generate: width in u of the distortion bump.");
DEFINE_double(axis_noise_deg, kFlankPath.axis_noise_deg,
              "generate: standard deviation of random tool-axis noise, deg.");
DEFINE_int32(noise_seed, 1, "generate: seed of the axis noise (results are deterministic).");
DEFINE_double(feed, kSettings.motion.default_feed_mm_per_min,
              "Programmed feed, mm/min (generate; default where a path has none).");

DEFINE_int32(samples_u, kSettings.deviation.samples_u, "Deviation grid: samples along u.");
DEFINE_int32(samples_v, kSettings.deviation.samples_v,
             "Deviation grid: samples along each ruling (v).");
DEFINE_string(interpolation, "",
              "evaluate/smooth: how the controller moves between blocks, for the deviation and "
              "the high_accuracy cost: tcp (tip linear in the workpiece, A and C linear) or joint "
              "(X Y Z A C linear). Empty: joint for joint-style G-code (the input's for "
              "evaluate, the output's for smooth), else tcp.");
DEFINE_bool(judge_on_input_range, kSettings.judge_on_input_range,
            "smooth: judge the output (report and tolerance check) on the grid of the input's "
            "covered u range, so a path that retreats from the surface's ends is charged for "
            "what it leaves; false judges the output on its own covered range.");
DEFINE_bool(even_stations, kSettings.even_stations,
            "smooth --mode=high_accuracy with a surface: solve each cutting stretch's poses at "
            "stations along the input's own motion where every move makes the same error "
            "(same pose count, same blocks), so that no long CAM move limits the accuracy; "
            "false solves every pose at the program's own station.");
DEFINE_int32(split_moves_for_tolerance, kSettings.split_moves_for_tolerance,
             "smooth --mode=high_accuracy with a surface and --even_stations: where the solve "
             "puts cutting runs back as programmed (for the tolerance or their peak d2), solve "
             "again at even stations with each cutting move split in two, then while runs "
             "still go back in four and eight, up to this many, keeping a result that puts "
             "fewer back; the split runs are written with the new poses between the "
             "program's. 1-8 (1 = never).");
DEFINE_bool(whole_surface, false,
            "Deviation grid over the whole surface (u in [0, 1]) instead of the u range the "
            "input covers; smooth judges its output on the same range as the input.");

DEFINE_string(mode, "high_accuracy",
              "smooth: spline (the seed's plain cubic-spline method, fast) or high_accuracy "
              "(Ceres least squares started from the spline result), or none (the input written "
              "back as read: a G-code program block for block).");
DEFINE_double(tolerance_mm, kSettings.high_accuracy.tolerance_mm,
              "high_accuracy: with a surface, the deviation unit of the cost, mm; without one, "
              "how far a tip may leave the original tip polyline, mm. stripwidth: the largest "
              "deviation (scallop) allowed across a strip, mm.");
DEFINE_double(angle_tolerance_deg, kSettings.high_accuracy.angle_tolerance_deg,
              "high_accuracy without a surface: how far a tool axis may turn from the "
              "original, deg.");
DEFINE_double(overcut_factor, kSettings.high_accuracy.overcut_factor,
              "high_accuracy: weight of overcut relative to undercut (>= 1).");
DEFINE_double(w_deviation, kSettings.high_accuracy.w_deviation,
              "high_accuracy: weight of the swept-cutter deviation.");
DEFINE_double(
    w_second, kSettings.high_accuracy.w_second,
    "high_accuracy: weight of d2(A,C)/ds2, mm^4/rad^2 (solver/smooth/cost/smoothness_cost.h).");
DEFINE_double(w_third, kSettings.high_accuracy.w_third,
              "high_accuracy: weight of d3(A,C)/ds3, mm^6/rad^2.");
DEFINE_double(ruling_departure_factor, kSettings.high_accuracy.ruling_departure_factor,
              "high_accuracy with a surface: where the rulings give the axis its angles, "
              "d2 and d3 are of A's and C's departure from them, at this many times "
              "w_second and w_third (0: of the angles themselves; "
              "solver/smooth/ruling_angles.h).");
DEFINE_double(end_of_cut_guard_weight, kSettings.high_accuracy.end_of_cut_guard_weight,
              "high_accuracy with a surface, joint interpolation: weight of the overcut guards "
              "inside the two moves either side of a cut's end pose, relative to the held "
              "point's own.");
DEFINE_double(w_tip_second, kSettings.high_accuracy.w_tip_second,
              "high_accuracy: weight of the tip's d2p/ds2, mm^2.");
DEFINE_double(w_tip_third, kSettings.high_accuracy.w_tip_third,
              "high_accuracy: weight of the tip's d3p/ds3, mm^4.");
DEFINE_double(w_limits, kSettings.high_accuracy.w_limits,
              "high_accuracy: weight of axis velocity/acceleration/jerk excess.");
DEFINE_double(limit_margin, kSettings.high_accuracy.limit_margin,
              "high_accuracy: limit penalties start at this fraction.");
DEFINE_double(w_tip_height, kSettings.high_accuracy.w_tip_height,
              "high_accuracy: weight holding each tip where the input had it along its axis "
              "relative to the floor (rail 0).");
DEFINE_double(w_tip_slide, kSettings.high_accuracy.w_tip_slide,
              "high_accuracy with a surface: weight holding each tip along the path where the "
              "solve starts it (0 = free to slide along it; then a stiffer step refused from "
              "both starts is solved again at 1, and the steps after it too).");
DEFINE_double(axis_cone_deg, kSettings.high_accuracy.axis_cone_deg,
              "high_accuracy with a surface: each tool axis stays within this angle of the "
              "input's, deg (0, 90].");
DEFINE_double(w_walls, kSettings.high_accuracy.w_walls,
              "high_accuracy: weight of the walls keeping each axis in its cone and on its side "
              "of the surface and each linear joint inside its travel (0 = off).");
DEFINE_int32(ruling_samples, kSettings.high_accuracy.ruling_samples,
             "high_accuracy: deviation samples along each ruling.");
DEFINE_int32(between_samples, kSettings.high_accuracy.between_samples,
             "high_accuracy: deviation checks inside each move.");
DEFINE_int32(max_iterations, kSettings.high_accuracy.max_iterations,
             "high_accuracy: Ceres iteration limit.");
DEFINE_int32(coarse_poses, kSettings.high_accuracy.coarse_poses,
             "high_accuracy: a path of more than twice this many poses is solved coarse to fine, "
             "over every 8th pose down to about this many (0 = always solve in full).");
DEFINE_int32(refine_iterations, kSettings.high_accuracy.refine_iterations,
             "high_accuracy: iteration limit of the full refinement after a coarse solve.");
DEFINE_int32(window_poses, kSettings.high_accuracy.window_poses,
             "high_accuracy: longer problems are solved in overlapping windows of this many poses, "
             "which bounds the memory (0 = never).");
DEFINE_double(pole_passage_deg, kSettings.high_accuracy.pole_passage_deg,
              "smooth: a pole passage is a stretch whose axis passes within this angle of A = 0 "
              "while C turns a quarter turn or more; high_accuracy also solves each the other way "
              "round the pole, spline may route it through the pole (0 = never).");
DEFINE_int32(pole_window_path_poses, kSettings.high_accuracy.pole_window_path_poses,
             "high_accuracy: on a longer path each pole passage is solved the other way in a "
             "window round it, not by solving the whole path again (0 = always the whole path).");
DEFINE_int32(num_threads, kSettings.high_accuracy.num_threads,
             "high_accuracy: Ceres threads (the same count gives the same result).");
DEFINE_double(spline_tolerance_deg, kSettings.spline.angle_tolerance_deg,
              "spline: largest A/C change the fit may make outside the abrupt zones, deg "
              "(sets the smoothing).");
DEFINE_bool(smooth_outside_zones, kSettings.spline.smooth_outside_zones,
            "spline: move every pose onto the fitted A/C curves, not only the abrupt zones.");
DEFINE_double(zone_factor, kSettings.spline.zone_factor,
              "spline: a zone is where |d2A/ds2|, |d2C/ds2| or |dK/ds| exceeds this x median.");
DEFINE_int32(zone_padding, kSettings.spline.zone_padding,
             "spline: poses added on each side of a zone.");
DEFINE_bool(insert_transitions, kSettings.spline.insert_transitions,
            "spline: insert a transition pose in every zone move.");
DEFINE_double(pole_crossing_deg, kSettings.spline.pole_crossing_deg,
              "spline: a pole passage whose axes all lie within this angle of one plane through "
              "A = 0 is put on that plane, so A changes sign there with C held (0 = never).");
DEFINE_bool(keep_runs_no_worse, kSettings.keep_runs_no_worse,
            "smooth: put back as programmed every cutting run that smoothing made worse on peak "
            "d2A/ds2 or d2C/ds2 (false: write what the method made); high_accuracy with a "
            "surface and without --accept_over_tolerance keeps a rougher run where the "
            "programmed one leaves a surface point beyond --tolerance_mm and the smoothed one "
            "stays within --stiffer_above_flank_d2 times the flank path's peaks (the report "
            "lists them).");
DEFINE_double(stiffer_above_flank_d2, kSettings.stiffer_above_flank_d2,
              "smooth: high_accuracy with a surface solves again with stiffer smoothing where "
              "its peak d2A/ds2 or d2C/ds2 is above this many times the surface's own flank "
              "(SPO) path's (0 = never).");
DEFINE_int32(stiffer_solves, kSettings.stiffer_solves,
             "smooth: high_accuracy with a surface solves again with stiffer smoothing (each "
             "time ten times the last's weights) at most this many times in turn, 0-8 (0 = "
             "none).");
DEFINE_double(peak_d2_cap_over_flank, kSettings.peak_d2_cap_over_flank,
              "smooth: high_accuracy with a surface: where the stiffer solves are spent or "
              "refused on a path still above --stiffer_above_flank_d2, one solve more keeps the "
              "weights and caps peak d2A/ds2 and d2C/ds2 at this many times the flank (SPO) "
              "path's instead (0 = no such solve).");
DEFINE_double(w_peak_second, kSettings.high_accuracy.w_peak_second,
              "high_accuracy: weight of the cap that --peak_d2_cap_over_flank sets "
              "(dimensionless, one-sided, >= 0).");
DEFINE_int32(peak_deviation_rounds, kSettings.peak_deviation_rounds,
             "smooth: high_accuracy with a surface solves again up to this many times to lower "
             "the result's worst deviation, holding the grid points farther than half of it (on "
             "every other grid line; 0.7 of it where nothing at half is kept); "
             "each round kept only where it keeps the tolerance and roughens no axis beyond "
             "--stiffer_above_flank_d2 times the flank path's (0 = none, faster).");
DEFINE_bool(accept_over_tolerance, kSettings.accept_over_tolerance,
            "smooth: with a surface, write a high_accuracy result even where it is farther from "
            "the surface than --tolerance_mm (by default it is refused, exit 3, nothing written).");
DEFINE_double(link_feed_ratio, kLinks.feed_ratio,
              "smooth, evaluate: a feed move at this many times the median feed or more is a "
              "link between cuts, kept as programmed like a rapid and not smoothed across "
              "(model/path/link_moves.h; 0 = no links).");
DEFINE_bool(schedule_feed, kSettings.schedule_feed,
            "smooth: lower the feed move by move where an axis would still exceed its velocity, "
            "acceleration or jerk limit (solver/smooth/feed_scheduler.h).");
DEFINE_string(cnc_summary, "",
              "smooth, evaluate: summary.json of benchmarks/linuxcnc/run.sh for the program this "
              "command writes (smooth) or reads (evaluate): the report and the HTML report show "
              "the controller's cycle time, stops and A/C motion beside tpopt's prediction.");
DEFINE_string(feed_mode, "lower",
              "smooth, with --schedule_feed: lower (feeds only come down, where a limit needs) "
              "or raise (every feed move starts at min(--max_feed_mm_per_min, "
              "--max_feed_factor x its programmed feed) and comes down where a limit needs) "
              "or keep_run_time (each cutting run keeps its time at the programmed feeds, spread "
              "over its moves by the program's tip speed averaged over "
              "--keep_run_time_window_mm; then lowered where a limit needs).");
DEFINE_bool(raise_within_input_peaks, kSettings.feed.keep_input_peaks,
            "smooth, --feed_mode=raise: no axis's acceleration or jerk above the input "
            "program's own peak over its cuts (nor above the machine's limit).");
DEFINE_double(keep_run_time_window_mm, kSettings.feed.keep_run_time_window_mm,
              "smooth, --feed_mode=keep_run_time: path length over which the program's tip "
              "speed is averaged, mm (> 0; inf = one speed per run).");
DEFINE_double(max_feed_mm_per_min, 0.0,
              "smooth, --feed_mode=raise: highest feed of any move, mm/min (0 = no cap but "
              "--max_feed_factor).");
DEFINE_double(max_feed_step, kSettings.feed.max_feed_step,
              "smooth, with --schedule_feed: largest relative change of feed between "
              "neighbouring feed moves that the scheduler makes (> 0).");
DEFINE_double(max_feed_factor, kSettings.feed.max_feed_factor,
              "smooth, --feed_mode=raise: highest feed of a move as a factor of its programmed "
              "feed (>= 1).");
DEFINE_double(resample_step_mm, kSettings.resample_step_mm,
              "smooth: resample the output with cubic splines through the tip and A, C at this "
              "arc-length step, mm (0 keeps the input's poses).");

DEFINE_string(method, "mpec",
              "stripwidth: sturz (fixed lead, no tilt), mpm (multi-point: widest gouge-free "
              "strip touching at the CC point) or mpec (mid-point error control: widest "
              "gouge-free strip centred on the CC point).");
DEFINE_string(cutter, "", "stripwidth: the cutter, torus:R,r (outer and corner radius, mm).");
DEFINE_int32(cc_points, 40, "stripwidth: CC points along the pass (v = --path_v, u in [0.05, 0.95]).");
DEFINE_double(path_v, kStripPath.path_v,
              "stripwidth: the surface parameter v of the pass, in [0, 1].");
DEFINE_double(lead_deg, 10.0, "stripwidth: Sturz's fixed lead angle, deg.");
DEFINE_double(min_lead_deg, 1.0, "stripwidth: least lead angle mpm and mpec may use, deg (> 0).");
DEFINE_double(max_lead_deg, 40.0, "stripwidth: largest lead angle mpm and mpec may use, deg.");
DEFINE_double(max_tilt_deg, 20.0, "stripwidth: largest |tilt| angle mpm and mpec may use, deg.");
DEFINE_int32(section_samples, 80,
             "stripwidth: cross-section samples each side of a CC point, over 2 R.");

DEFINE_string(output_curve, "points",
              "smooth, pencil: points (the poses as they are) or bspline (the seed-004 local "
              "cubic B-spline fit of each run, written as NURBS/ span records plus points "
              "resampled on the spans; G-code gets the points only).");
DEFINE_double(curve_step_mm, kCurveOutput.sample_step_mm,
              "--output_curve=bspline: largest chord step between resampled points, mm.");
DEFINE_string(fit_parametrization, "approximate_arc",
              "--output_curve=bspline: knots from approximate_arc (seed 004), chord, "
              "centripetal or uniform parameters.");
DEFINE_string(fit_chord_height, "neighbours",
              "--output_curve=bspline: chord height delta of the approximate arc: fixed "
              "(--fit_chord_height_mm, as the seed states it) or neighbours (the sagitta of the "
              "circle through each chord and its neighbour point).");
DEFINE_double(fit_chord_height_mm, kCurveOutput.fit.chord_height_mm,
              "--fit_chord_height=fixed: delta, mm (the CL path's machining accuracy).");

DEFINE_string(curve, "", "pencil: planar guide curves JSON (kind planar_curves).");
DEFINE_double(ball_radius, kPencil.ball_radius_mm, "pencil: ball-end cutter radius, mm.");
DEFINE_double(interpolation_period_ms, 8.0,
              "pencil: interpolation period, ms; CC points are feed x period apart.");

DEFINE_string(tool_table, "",
              "evaluate, smooth: a LinuxCNC tool table (T1 P1 D6 Z12.5 ;comment) that sizes the "
              "tools a G-code program loads (T, M6, M61): each tool's D is its cutter's "
              "diameter. Empty: the [EMCIO] TOOL_TABLE of a --machine INI, if any.");

DEFINE_string(part_setup, "",
              "evaluate, smooth: where an APT program's part frame sits on the table, "
              "tx,ty,tz,rx,ry,rz (mm, deg): p_table = Rz Ry Rx p_part + t. Empty: the "
              "program's frame is the table's. APT output is written back in the part frame.");
