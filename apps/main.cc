// tpopt: smooth 5-axis flank-milling tool paths. See README.md.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "apps/commands.h"
#include "apps/exit_codes.h"
#include "apps/flag_parser.h"
#include "apps/flags.h"
#include "apps/huge_page_malloc.h"
#include "apps/version.h"

namespace {

constexpr char kUsage[] =
    "usage: tpopt <subcommand> [--flag=value ...] [--flagfile=F]\n"
    "\n"
    "subcommands:\n"
    "  generate  --surface=S --cutter_radius=R --poses=N --strategy=spo|dpo\n"
    "            [--uv_distortion=AMP] [--axis_noise_deg=D] --out=P.cls\n"
    "  evaluate  --in=P [--surface=S] [--machine=M] --report=R.json\n"
    "  smooth    --in=P --out=Q [--surface=S] [--machine=M] --mode=spline|high_accuracy|none\n"
    "            [weights...] --report=R.json [--output_curve=points|bspline]\n"
    "  pencil    --surface=S.json --curve=C.json --ball_radius=R --out=P.cls\n"
    "            [--feed=F] [--interpolation_period_ms=T] [--output_curve=points|bspline]\n"
    "            [--report=R.json]\n"
    "  stripwidth --surface=S.json --method=sturz|mpm|mpec --cutter=torus:R,r\n"
    "            --tolerance_mm=H --out=P.cls [--machine=M] [--report=R.json]\n"
    "\n"
    "Exit codes: 0 success, 1 bad input, 2 usage, 3 solver failure.\n"
    "`tpopt --help` lists every flag.\n";

}  // namespace

int main(int argc, char** argv) {
  tpopt::RestartWithHugePageMalloc(argv);
  gflags::SetUsageMessage(kUsage);
  gflags::SetVersionString(tpopt::kTpoptVersion);
  FLAGS_logtostderr = true;
  google::InitGoogleLogging(argv[0]);
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return tpopt::kExitUsage;
  }
  const std::string sub = argv[1];
  if (sub == "--help" || sub == "-h" || sub == "help") {
    gflags::ShowUsageWithFlagsRestrict(argv[0], "apps/flags");
    return tpopt::kExitSuccess;
  }
  if (sub == "--version") {
    std::printf("tpopt %s\n", gflags::VersionString());
    return tpopt::kExitSuccess;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  // Help after a subcommand is help, before any check of the subcommand's
  // own flags (`tpopt pencil --help` must not answer "--surface is required").
  for (const std::string& arg : args) {
    if (arg == "--helpfull" || arg == "-helpfull") {
      gflags::ShowUsageWithFlags(argv[0]);
      return tpopt::kExitSuccess;
    }
    if (arg == "--help" || arg == "-help" || arg == "-h" || arg == "--helpshort") {
      gflags::ShowUsageWithFlagsRestrict(argv[0], "apps/flags");
      return tpopt::kExitSuccess;
    }
  }
  std::vector<std::string> positional;
  const tpopt::Status parsed = tpopt::ParseFlags(args, &positional);
  if (!parsed.ok()) {
    std::fprintf(stderr, "tpopt %s: %s\n", sub.c_str(), parsed.message().c_str());
    return tpopt::kExitUsage;
  }
  if (!positional.empty()) {
    std::fprintf(stderr, "tpopt %s: unexpected argument '%s'\n%s", sub.c_str(),
                 positional.front().c_str(), kUsage);
    return tpopt::kExitUsage;
  }
  const tpopt::Invocation invocation{tpopt::JoinCommandLine(argc, argv)};
  if (sub == "generate") return tpopt::RunGenerate(invocation);
  if (sub == "evaluate") return tpopt::RunEvaluate(invocation);
  if (sub == "smooth") return tpopt::RunSmooth(invocation);
  if (sub == "stripwidth") return tpopt::RunStripWidth(invocation);
  if (sub == "pencil") return tpopt::RunPencil(invocation);
  std::fprintf(stderr, "tpopt: unknown subcommand '%s'\n%s", sub.c_str(), kUsage);
  return tpopt::kExitUsage;
}
