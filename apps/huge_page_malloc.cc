#include "apps/huge_page_malloc.h"

#include <sys/auxv.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

namespace tpopt {
namespace {

constexpr char kTunable[] = "glibc.malloc.hugetlb";
constexpr char kTunableOn[] = "glibc.malloc.hugetlb=1";
// Set on the restarted process, so that it never restarts again (glibc
// drops GLIBC_TUNABLES in secure mode, and a loop must be impossible).
constexpr char kRestartMarker[] = "TPOPT_HUGE_PAGES_RESTARTED";

std::string ReadThpMode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

bool RunsUnderAddressSanitizer() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#else
  return false;
#endif
#else
  return false;
#endif
}

bool ShouldRestartForHugePages(const char* glibc_tunables, const char* tpopt_huge_pages,
                               const char* restart_marker, const char* thp_mode) {
  if (restart_marker != nullptr) return false;
  if (tpopt_huge_pages != nullptr && std::strcmp(tpopt_huge_pages, "0") == 0) return false;
  if (glibc_tunables != nullptr && std::strstr(glibc_tunables, kTunable) != nullptr) return false;
  // The kernel marks its mode in brackets: "always [madvise] never". Under
  // "always" every large mapping gets huge pages already; under "never" none
  // can.
  return thp_mode != nullptr && std::strstr(thp_mode, "[madvise]") != nullptr;
}

bool HugePageMallocActive() {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return !RunsUnderAddressSanitizer() && tunables != nullptr &&
         std::strstr(tunables, kTunableOn) != nullptr;
}

void RestartWithHugePageMalloc(char** argv) {
  if (RunsUnderAddressSanitizer() || getauxval(AT_SECURE) != 0) return;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (!ShouldRestartForHugePages(tunables, std::getenv("TPOPT_HUGE_PAGES"),
                                 std::getenv(kRestartMarker), ReadThpMode().c_str())) {
    return;
  }
  std::string value = kTunableOn;
  if (tunables != nullptr && *tunables != '\0') value = std::string(tunables) + ":" + value;
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0 || setenv(kRestartMarker, "1", 1) != 0) {
    return;
  }
  execv("/proc/self/exe", argv);
  // Not restarted (no /proc, or the binary was replaced): run as we are,
  // without leaving the half-made change for child processes.
  if (tunables != nullptr) {
    setenv("GLIBC_TUNABLES", tunables, 1);
  } else {
    unsetenv("GLIBC_TUNABLES");
  }
  unsetenv(kRestartMarker);
}

}  // namespace tpopt
