#include "solver/smooth/tolerance_promise.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

#include <glog/logging.h>

namespace tpopt {

std::vector<size_t> BeyondTolerance(const std::vector<double>& allowance_mm,
                                    const DeviationReport& out, double tolerance_mm,
                                    double slack_mm) {
  CHECK_EQ(allowance_mm.size(), out.deviation_mm.size());
  std::vector<size_t> beyond;
  for (size_t k = 0; k < out.deviation_mm.size(); ++k) {
    const double d = std::abs(out.deviation_mm[k]);
    if (d > tolerance_mm && d > allowance_mm[k] + slack_mm) beyond.push_back(k);
  }
  return beyond;
}

bool SameBeyondPoints(const DeviationReport& before, const std::vector<size_t>& beyond_before,
                      const DeviationReport& after, const std::vector<size_t>& beyond_after,
                      double within_mm) {
  if (beyond_after.empty() || beyond_after != beyond_before) return false;
  for (const size_t k : beyond_after) {
    if (!(std::abs(after.deviation_mm[k] - before.deviation_mm[k]) <= within_mm)) return false;
  }
  return true;
}

std::vector<double> InputAllowance(const DeviationReport& in, std::vector<double> input_u) {
  std::sort(input_u.begin(), input_u.end());
  const size_t nu = in.u.size(), nv = in.v.size();
  std::vector<double> allowance(in.deviation_mm.size(), 0.0);
  if (input_u.empty()) return allowance;
  for (size_t iu = 0; iu < nu; ++iu) {
    // The poses' rulings either side (at a pose's own ruling, both moves
    // out of it cut the point).
    const auto below = std::lower_bound(input_u.begin(), input_u.end(), in.u[iu]);
    const auto above = std::upper_bound(input_u.begin(), input_u.end(), in.u[iu]);
    const double lo = below == input_u.begin() ? input_u.front() : *std::prev(below);
    const double hi = above == input_u.end() ? input_u.back() : *above;
    // (The grid's u ascend.)
    const size_t first = std::min<size_t>(
        iu, std::lower_bound(in.u.begin(), in.u.end(), lo) - in.u.begin());
    const size_t last = std::max<size_t>(
        iu + 1, std::upper_bound(in.u.begin(), in.u.end(), hi) - in.u.begin());
    for (size_t ju = first; ju < last; ++ju) {
      for (size_t iv = 0; iv < nv; ++iv) {
        double& a = allowance[iu * nv + iv];
        a = std::max(a, std::abs(in.deviation_mm[ju * nv + iv]));
      }
    }
  }
  return allowance;
}

std::string BeyondToleranceMessage(const DeviationReport& in, const DeviationReport& out,
                                   const std::vector<size_t>& beyond, double tolerance_mm) {
  CHECK(!beyond.empty());
  const size_t worst = *std::max_element(beyond.begin(), beyond.end(), [&](size_t a, size_t b) {
    return std::abs(out.deviation_mm[a]) < std::abs(out.deviation_mm[b]);
  });
  const size_t nv = out.v.size();
  std::ostringstream err;
  err << "the best path found is " << std::abs(out.deviation_mm[worst]) << " mm "
      << (out.deviation_mm[worst] < 0 ? "into" : "short of") << " the surface at (u "
      << out.u[worst / nv] << ", v " << out.v[worst % nv] << "), where the input was "
      << std::abs(in.deviation_mm[worst]) << " mm: beyond the tolerance of " << tolerance_mm
      << " mm at " << beyond.size() << " of " << out.deviation_mm.size() << " grid points";
  return err.str();
}

}  // namespace tpopt
