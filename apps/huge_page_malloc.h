// Large buffers in transparent huge pages.
//
// A long path touches a few hundred MB of fresh memory per smoothing run
// (the spline method at a million poses, Ceres' Jacobians at ten
// thousand). At 4 KiB a page that is tens of thousands of page faults, and
// on a virtual machine each costs microseconds: on the development VM the
// faults were over a third of the spline method's time at 1M poses.
// glibc (2.35 and later) can ask the kernel for transparent huge pages for
// what it maps (the tunable glibc.malloc.hugetlb=1, which madvises them:
// the kernel's THP mode "madvise", Debian's default), but it reads its tunables
// only at start-up, from GLIBC_TUNABLES. So a program calls this first
// thing in main() and, if the tunable is not yet set, restarts itself once
// with it added to the environment. Large paths run faster with it (README,
// "Figures behind the defaults").
//
// It leaves the process as it is, and returns, when: the user's
// GLIBC_TUNABLES already names glibc.malloc.hugetlb (theirs is kept,
// whatever it says); TPOPT_HUGE_PAGES=0; the kernel's THP mode is not
// "madvise" ("always" has them already, "never" cannot);
// the process runs set-user-ID (glibc ignores tunables then); it has
// already restarted once; it runs under AddressSanitizer (whose allocator
// is not glibc's); or the restart itself fails.
#ifndef TPOPT_APPS_HUGE_PAGE_MALLOC_H_
#define TPOPT_APPS_HUGE_PAGE_MALLOC_H_

namespace tpopt {

// Does not return when it restarts the program (same argv, same pid).
void RestartWithHugePageMalloc(char** argv);

// Whether RestartWithHugePageMalloc would restart, given the values of
// GLIBC_TUNABLES, TPOPT_HUGE_PAGES and the restart marker (null when
// unset) and the text of /sys/kernel/mm/transparent_hugepage/enabled
// (empty when unreadable). Separate so it can be tested.
bool ShouldRestartForHugePages(const char* glibc_tunables, const char* tpopt_huge_pages,
                               const char* restart_marker, const char* thp_mode);

// Whether this build runs under AddressSanitizer, whose allocator replaces
// glibc's (and so ignores the tunable).
bool RunsUnderAddressSanitizer();

// Whether this process's malloc asks for huge pages (glibc.malloc.hugetlb=1
// in effect), as the reports record beside their timings.
bool HugePageMallocActive();

}  // namespace tpopt

#endif  // TPOPT_APPS_HUGE_PAGE_MALLOC_H_
