// Both smoothing modes under both interpolation models on random cases
// (model/eval/random_cases.h): the distribution over the cases of max |dev| /
// the clean DPO path's, the peak d2A/ds2 and d2C/ds2 / the clean SPO path's,
// refusals, failures and time. Prints a Markdown table; `--out=FILE.csv`
// also writes one row per case and configuration.
//
//   ./build/benchmarks/random_case_benchmark [--cases=200] [--first_seed=1]
//       [--poses=40] [--out=random_cases.csv] [--seeds=3,17,29]
//       [--mode=spline|high_accuracy] [--interpolation=tcp|joint]
//       [--even_stations=false] [--accept_over_tolerance]
//       [--peak_d2_cap_over_flank=1.5]
//
// --seeds runs the listed seeds instead of --cases from --first_seed;
// --mode and --interpolation run only the configurations that match (for
// diagnosing single cases); --even_stations=false solves high accuracy at
// the CAM's own stations (solver/smooth/even_stations.h);
// --accept_over_tolerance lifts the tolerance promise
// (solver/smooth/tolerance_promise.h), as the tool's flag does, to measure
// what the promise costs against the targets; --peak_d2_cap_over_flank sets
// the capped stiffer step's cap as the tool's flag does (0: no capped step).
// With --seeds every
// refusal also prints the case's description and the input's and initial
// guess's max |dev|.
//
// Against issue 16's targets (max |dev| <= 1.0 x the DPO path's, peak d2A
// and d2C <= 2 x the SPO path's) the table counts the cases that meet the
// d2 one, all three, and all three with each d2 held to the larger of
// 2 x SPO and the clean DPO path's own (where the accurate reference is
// itself beyond 2 x SPO, as where it passes the A = 0 pole at a distance
// that the SPO path's axis does not keep, the two targets pull apart); the
// CSV has the DPO path's own d2 ratios per case, and the grid points at
// which the clean DPO path itself breaks the tolerance promise against the
// CAM input (beyond the tolerance where the input was within it), a sign
// that the promise and the deviation target pull apart there too.
//
// Deviation is that of the pipeline's own report (the fast exact evaluator
// on the input's covered range, under the configuration's interpolation
// model); the DPO reference is evaluated on the same grid and model. A
// case whose input does not fit its machine is counted apart and not run.
// A refusal is a solver failure (nothing written: kSolver); a failure is
// any other error on an input that fits, which should not happen.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "model/eval/path_metrics.h"
#include "model/eval/random_cases.h"
#include "model/io/atomic_file.h"
#include "model/io/json_io.h"
#include "solver/smooth/smoothing_pipeline.h"
#include "solver/smooth/tolerance_promise.h"

namespace tpopt {
namespace {

struct Config {
  SmoothingMode mode;
  Interpolation interpolation;
  const char* ModeName() const { return mode == SmoothingMode::kSpline ? "spline" : "high_accuracy"; }
};

struct Row {
  unsigned seed = 0;
  std::string machine, config_mode, interpolation, outcome, message;
  double dev_ratio = NAN, a_ratio = NAN, c_ratio = NAN, time_s = 0;
  // The clean DPO path's own peak d2A and d2C over the SPO path's.
  double dpo_a_ratio = NAN, dpo_c_ratio = NAN;
  // Grid points where the clean DPO path breaks the tolerance promise.
  size_t dpo_promise_breaks = 0;
};

// A reference path's evaluation on the judge's grid and model, and the
// grid points at which it breaks the tolerance promise against the input.
struct Reference {
  PathMetrics metrics;
  size_t promise_breaks = 0;
};

std::string Data(const std::string& relative) {
  return std::string(TPOPT_SOURCE_DIR) + "/data/" + relative;
}

// The p-quantile (nearest rank) of `values`, NaN when empty.
double Quantile(std::vector<double> values, double p) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const size_t rank = static_cast<size_t>(std::ceil(p * values.size()));
  return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

// Issue 16's target for the peak d2A/ds2 and d2C/ds2: this many times the
// clean SPO path's.
constexpr double kD2Target = 2.0;

// The cases (seeds; a case's rows are consecutive) with a row that meets
// `pred`.
template <typename Pred>
size_t CasesWhere(const std::vector<Row>& rows, Pred pred) {
  size_t cases = 0;
  const Row* last_counted = nullptr;
  for (const Row& row : rows) {
    if (!pred(row) || (last_counted != nullptr && last_counted->seed == row.seed)) continue;
    ++cases;
    last_counted = &row;
  }
  return cases;
}

double Ratio(double value, double reference) {
  return reference > 0 ? value / reference : (value > 0 ? INFINITY : 1.0);
}

// `base`: the settings every configuration shares.
Row RunCase(const RandomCase& c, const Config& config, const Reference& dpo_reference,
            const PathMetrics& spo, const SmoothingSettings& base, bool detail) {
  const PathMetrics& dpo = dpo_reference.metrics;
  SmoothingSettings settings = base;
  settings.mode = config.mode;
  settings.deviation.interpolation = config.interpolation;
  SmoothingResult result;
  const auto start = std::chrono::steady_clock::now();
  const Status s =
      RunSmoothing({&c.cam_path, &c.surface, &c.cutter, &c.machine}, settings, &result);
  Row row;
  row.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  row.seed = c.seed;
  row.machine = c.machine.name;
  row.config_mode = config.ModeName();
  row.interpolation = InterpolationName(config.interpolation);
  row.dpo_a_ratio = Ratio(dpo.motion.axes[kA].peak_second_derivative_per_mm2,
                          spo.motion.axes[kA].peak_second_derivative_per_mm2);
  row.dpo_c_ratio = Ratio(dpo.motion.axes[kC].peak_second_derivative_per_mm2,
                          spo.motion.axes[kC].peak_second_derivative_per_mm2);
  row.dpo_promise_breaks = dpo_reference.promise_breaks;
  if (!s.ok()) {
    row.outcome = s.code() == StatusCode::kSolver ? "refused" : "failed";
    row.message = s.message();
    if (detail) {
      char numbers[200];
      std::snprintf(numbers, sizeof(numbers),
                    " [max|dev| input %.4g, guess %.4g, output %.4g, clean DPO %.4g mm] ",
                    WorstDeviationMm(result.input_metrics),
                    WorstDeviationMm(result.initial_guess_metrics),
                    WorstDeviationMm(result.output_at_input_feed), WorstDeviationMm(dpo));
      row.message += numbers + c.description;
    }
    return row;
  }
  row.outcome = "ok";
  // What shaped the result: runs the never-worse rule put back as the
  // input's (with the input's deviation), and solves repeated stiffer.
  row.message = "runs kept as input " + std::to_string(result.runs_kept_as_input) +
                ", stiffer solves " + std::to_string(result.stiffer_solves) + " (tips held " +
                std::to_string(result.stiffer_solves_tips_held) + ", capped " +
                std::to_string(result.stiffer_solves_capped) + "), last eased " +
                std::to_string(result.stiffer_solves_eased) + ", peak-deviation rounds " +
                std::to_string(result.peak_deviation_rounds) + " (at 0.7 " +
                std::to_string(result.peak_rounds_at_milder_bound) + ")";
  for (const KeptRun& kept : result.runs_kept) {
    char why[200];
    std::snprintf(why, sizeof(why), "; poses %d-%d %s%s %.3g->%.3g at u %.3f v %.3f",
                  kept.first_line, kept.last_line, kept.reason.c_str(), kept.axis.c_str(),
                  kept.reason == "tolerance" ? kept.input_mm : kept.input_peak,
                  kept.reason == "tolerance" ? kept.worst_mm : kept.smoothed_peak, kept.u, kept.v);
    row.message += why;
  }
  const MotionReport& out = result.output_metrics.motion;
  row.dev_ratio = Ratio(WorstDeviationMm(result.output_metrics), WorstDeviationMm(dpo));
  row.a_ratio = Ratio(out.axes[kA].peak_second_derivative_per_mm2,
                      spo.motion.axes[kA].peak_second_derivative_per_mm2);
  row.c_ratio = Ratio(out.axes[kC].peak_second_derivative_per_mm2,
                      spo.motion.axes[kC].peak_second_derivative_per_mm2);
  return row;
}

std::string CsvField(std::string text) {
  std::replace(text.begin(), text.end(), '"', '\'');
  return "\"" + text + "\"";
}

int Main(int argc, char** argv) {
  int cases = 200, poses = 40;
  unsigned first_seed = 1;
  std::string csv_path, only_mode, only_interpolation;
  std::vector<unsigned> seeds;
  SmoothingSettings base;
  base.judge_on_input_range = true;
  for (int i = 1; i < argc; ++i) {
    const char* arg = argv[i];
    if (std::strncmp(arg, "--cases=", 8) == 0) {
      cases = std::atoi(arg + 8);
    } else if (std::strncmp(arg, "--poses=", 8) == 0) {
      poses = std::atoi(arg + 8);
    } else if (std::strncmp(arg, "--first_seed=", 13) == 0) {
      first_seed = static_cast<unsigned>(std::strtoul(arg + 13, nullptr, 10));
    } else if (std::strncmp(arg, "--out=", 6) == 0) {
      csv_path = arg + 6;
    } else if (std::strncmp(arg, "--seeds=", 8) == 0) {
      std::istringstream list(arg + 8);
      for (std::string item; std::getline(list, item, ',');) {
        seeds.push_back(static_cast<unsigned>(std::strtoul(item.c_str(), nullptr, 10)));
      }
    } else if (std::strncmp(arg, "--mode=", 7) == 0) {
      only_mode = arg + 7;
    } else if (std::strncmp(arg, "--interpolation=", 16) == 0) {
      only_interpolation = arg + 16;
    } else if (std::strcmp(arg, "--even_stations=false") == 0) {
      base.even_stations = false;
    } else if (std::strcmp(arg, "--accept_over_tolerance") == 0) {
      base.accept_over_tolerance = true;
    } else if (std::strncmp(arg, "--peak_d2_cap_over_flank=", 25) == 0) {
      base.peak_d2_cap_over_flank = std::strtod(arg + 25, nullptr);
    } else {
      std::fprintf(stderr,
                   "usage: %s [--cases=200] [--first_seed=1] [--poses=40] [--out=FILE.csv] "
                   "[--seeds=a,b,c] [--mode=spline|high_accuracy] [--interpolation=tcp|joint] "
                   "[--even_stations=false] [--accept_over_tolerance] "
                   "[--peak_d2_cap_over_flank=1.5]\n",
                   argv[0]);
      return 2;
    }
  }
  std::vector<Machine> machines(2);
  for (size_t k = 0; k < 2; ++k) {
    const char* name = k == 0 ? "machines/jcde2022_ac.json" : "machines/linuxcnc_xyzac_trt_sim.json";
    const Status s = ReadMachineJson(Data(name), &machines[k]);
    if (!s.ok()) {
      std::fprintf(stderr, "%s\n", s.message().c_str());
      return 1;
    }
  }
  RandomCaseOptions options;
  options.poses = poses;
  if (std::string why; !options.IsValid(&why) || cases < 1) {
    std::fprintf(stderr, "bad options: %s (cases %d)\n", why.c_str(), cases);
    return 2;
  }
  std::vector<Config> configs;
  for (const Config& config : {Config{SmoothingMode::kSpline, Interpolation::kTcp},
                               Config{SmoothingMode::kSpline, Interpolation::kJoint},
                               Config{SmoothingMode::kHighAccuracy, Interpolation::kTcp},
                               Config{SmoothingMode::kHighAccuracy, Interpolation::kJoint}}) {
    if ((only_mode.empty() || only_mode == config.ModeName()) &&
        (only_interpolation.empty() ||
         only_interpolation == InterpolationName(config.interpolation))) {
      configs.push_back(config);
    }
  }
  if (configs.empty()) {
    std::fprintf(stderr, "no configuration matches --mode=%s --interpolation=%s\n",
                 only_mode.c_str(), only_interpolation.c_str());
    return 2;
  }
  const bool detail = !seeds.empty();
  if (seeds.empty()) {
    for (int k = 0; k < cases; ++k) seeds.push_back(first_seed + static_cast<unsigned>(k));
  }
  cases = static_cast<int>(seeds.size());
  std::vector<Row> rows;
  int not_fitting = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const unsigned seed : seeds) {
    RandomCase c;
    const Status s = MakeRandomCase(seed, options, machines, &c);
    if (!s.ok()) {
      std::fprintf(stderr, "seed %u: %s\n", seed, s.message().c_str());
      return 1;
    }
    if (!c.fits_machine) {
      ++not_fitting;
      std::fprintf(stderr, "\nseed %u does not fit %s: %s\n", c.seed, c.machine.name.c_str(),
                   c.fit_note.c_str());
      continue;
    }
    double u_min = 0, u_max = 1;
    CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max);
    // The references under each model (index: Interpolation), on the grid
    // the pipeline judges the output on.
    Reference dpo[2];
    PathMetrics spo;
    for (const Interpolation model : {Interpolation::kTcp, Interpolation::kJoint}) {
      DeviationOptions deviation;
      deviation.u_min = u_min;
      deviation.u_max = u_max;
      deviation.interpolation = model;
      Reference& reference = dpo[static_cast<int>(model)];
      PathMetrics input;
      Status r = EvaluatePath(c.clean_dpo, c.machine, &c.surface, c.cutter, deviation,
                              MotionOptions(), &reference.metrics);
      if (r.ok()) {
        r = EvaluatePath(c.clean_spo, c.machine, nullptr, c.cutter, deviation, MotionOptions(),
                         &spo);
      }
      if (r.ok()) {
        r = EvaluatePath(c.cam_path, c.machine, &c.surface, c.cutter, deviation, MotionOptions(),
                         &input);
      }
      if (r.ok()) {
        reference.promise_breaks =
            BeyondTolerance(
                InputAllowance(*input.deviation, CuttingContactU(c.surface, c.cam_path)),
                *reference.metrics.deviation, base.high_accuracy.tolerance_mm)
                .size();
      }
      if (!r.ok()) {
        std::fprintf(stderr, "seed %u: the references: %s\n", c.seed, r.message().c_str());
        return 1;
      }
    }
    for (const Config& config : configs) {
      rows.push_back(
          RunCase(c, config, dpo[static_cast<int>(config.interpolation)], spo, base, detail));
      if (rows.back().outcome != "ok") {
        std::fprintf(stderr, "\nseed %u %s %s %s: %s\n", c.seed, config.ModeName(),
                     InterpolationName(config.interpolation), rows.back().outcome.c_str(),
                     rows.back().message.c_str());
      }
    }
    std::fprintf(stderr, ".");
  }
  const double total_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "\n");

  std::printf("%d random cases (seeds %u-%u, %d CAM poses each), %d do not fit their machine; "
              "%.0f s in all\n\n",
              cases, *std::min_element(seeds.begin(), seeds.end()),
              *std::max_element(seeds.begin(), seeds.end()), poses, not_fitting, total_s);
  // The accurate reference's own peaks: where the clean DPO path is itself
  // beyond the d2 target, the deviation and d2 targets pull apart.
  std::printf(
      "The clean DPO path itself is beyond %.0f x the SPO path's peak d2A or d2C on %zu "
      "of the cases run.\n\n",
      kD2Target, CasesWhere(rows, [](const Row& row) {
        return row.dpo_a_ratio > kD2Target || row.dpo_c_ratio > kD2Target;
      }));
  // And where it breaks the tolerance promise against the CAM input, the
  // deviation target and the promise do (per interpolation model).
  for (const Interpolation model : {Interpolation::kTcp, Interpolation::kJoint}) {
    const auto under_model = [&](const Row& row) {
      return row.interpolation == InterpolationName(model);
    };
    if (CasesWhere(rows, under_model) == 0) continue;
    std::printf(
        "Under %s interpolation the clean DPO path itself breaks the tolerance promise "
        "(beyond %.3g mm where the CAM input was within it) on %zu of the cases run.\n\n",
        InterpolationName(model), base.high_accuracy.tolerance_mm,
        CasesWhere(rows,
                   [&](const Row& row) { return under_model(row) && row.dpo_promise_breaks > 0; }));
  }
  std::printf("| mode | interpolation | run | refused | failed | max\\|dev\\|/DPO median / p95 / "
              "worst | <= 0.7 | <= 1.0 | d2A/SPO median / p95 / worst | d2C/SPO median / p95 / "
              "worst | d2 both <= 2 | all three | all three, d2 <= DPO's own | time s median / "
              "p95 / worst |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Config& config : configs) {
    std::vector<double> dev, a, cc, time;
    int run = 0, refused = 0, failed = 0, within_07 = 0, within_10 = 0, d2_both = 0, all_three = 0,
        all_three_dpo = 0;
    for (const Row& row : rows) {
      if (row.config_mode != config.ModeName() ||
          row.interpolation != InterpolationName(config.interpolation)) {
        continue;
      }
      ++run;
      time.push_back(row.time_s);
      if (row.outcome == "refused") ++refused;
      if (row.outcome == "failed") ++failed;
      if (row.outcome != "ok") continue;
      dev.push_back(row.dev_ratio);
      a.push_back(row.a_ratio);
      cc.push_back(row.c_ratio);
      within_07 += row.dev_ratio <= 0.7;
      within_10 += row.dev_ratio <= 1.0;
      const bool d2 = row.a_ratio <= kD2Target && row.c_ratio <= kD2Target;
      d2_both += d2;
      all_three += d2 && row.dev_ratio <= 1.0;
      // (An infinite ratio, an SPO path that does not turn, fails both.)
      all_three_dpo += row.dev_ratio <= 1.0 && std::isfinite(row.a_ratio) &&
                       std::isfinite(row.c_ratio) &&
                       row.a_ratio <= std::max(kD2Target, row.dpo_a_ratio) &&
                       row.c_ratio <= std::max(kD2Target, row.dpo_c_ratio);
    }
    auto three = [](const std::vector<double>& v, const char* format) {
      char buf[96];
      std::snprintf(buf, sizeof(buf), format, Quantile(v, 0.5), Quantile(v, 0.95),
                    v.empty() ? NAN : *std::max_element(v.begin(), v.end()));
      return std::string(buf);
    };
    std::printf("| %s | %s | %d | %d | %d | %s | %d | %d | %s | %s | %d | %d | %d | %s |\n",
                config.ModeName(), InterpolationName(config.interpolation), run, refused, failed,
                three(dev, "%.2f / %.2f / %.2f").c_str(), within_07, within_10,
                three(a, "%.2f / %.2f / %.2f").c_str(), three(cc, "%.2f / %.2f / %.2f").c_str(),
                d2_both, all_three, all_three_dpo, three(time, "%.2f / %.2f / %.2f").c_str());
  }
  if (!csv_path.empty()) {
    std::ostringstream csv;
    csv << "seed,machine,mode,interpolation,outcome,dev_over_dpo,d2a_over_spo,d2c_over_spo,"
           "time_s,dpo_d2a_over_spo,dpo_d2c_over_spo,dpo_promise_breaks,message\n";
    for (const Row& row : rows) {
      char numbers[160];
      std::snprintf(numbers, sizeof(numbers), "%.6g,%.6g,%.6g,%.4f,%.6g,%.6g,%zu", row.dev_ratio,
                    row.a_ratio, row.c_ratio, row.time_s, row.dpo_a_ratio, row.dpo_c_ratio,
                    row.dpo_promise_breaks);
      csv << row.seed << "," << row.machine << "," << row.config_mode << "," << row.interpolation
          << "," << row.outcome << "," << numbers << "," << CsvField(row.message) << "\n";
    }
    const Status w = WriteFileAtomically(csv_path, csv.str());
    if (!w.ok()) {
      std::fprintf(stderr, "%s\n", w.message().c_str());
      return 1;
    }
  }
  return 0;
}

}  // namespace
}  // namespace tpopt

int main(int argc, char** argv) { return tpopt::Main(argc, argv); }
