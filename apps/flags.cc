#include "apps/flags.h"

DEFINE_string(surface, "", "Ruled surface JSON (DESIGN.md format).");
DEFINE_string(machine, "", "Machine JSON (xyzac-trt kinematics and axis limits).");
DEFINE_string(in, "", "Input tool path: APT CL (.cls, .apt).");
DEFINE_string(out, "", "Output tool path; written whole or not at all.");
DEFINE_string(report, "", "Report JSON to write (metrics of the input and output).");
DEFINE_bool(quiet, false, "No progress or summary on stderr.");

DEFINE_double(cutter_radius, 0.0,
              "Cutter radius, mm. generate: required. evaluate/smooth: overrides the "
              "path file's TLDATA/CUTTER (0 = use the file's).");
DEFINE_double(flute_length, 0.0,
              "Cutter flute length, mm (0 = the path file's, else 1.25 x the longest ruling).");

DEFINE_int32(poses, 300, "generate: number of poses along the surface.");
DEFINE_string(strategy, "spo", "generate: spo (single-point offset) or dpo (double-point offset).");
DEFINE_double(uv_distortion, 0.0,
              "generate: amplitude (in u) of a CAM-like U/V mismatch bump pairing C1(u) with "
              "C2(u + delta(u)); 0 = a clean path.");
DEFINE_double(distortion_center, 0.5, "generate: u at the centre of the distortion bump.");
DEFINE_double(distortion_width, 0.08, "generate: width in u of the distortion bump.");
DEFINE_double(axis_noise_deg, 0.0, "generate: standard deviation of random tool-axis noise, deg.");
DEFINE_int32(noise_seed, 1, "generate: seed of the axis noise (results are deterministic).");
DEFINE_double(feed, 1000.0, "Programmed feed, mm/min (generate; default where a path has none).");

DEFINE_int32(samples_u, 200, "Deviation grid: samples along u.");
DEFINE_int32(samples_v, 21, "Deviation grid: samples along each ruling (v).");
