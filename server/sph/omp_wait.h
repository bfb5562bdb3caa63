// How the project's programs' OpenMP threads wait for each other at the end of a parallel loop.
//
// libgomp's default spins for up to 300,000 pause loops before it sleeps, longer than most of a
// step's phases. On a shared machine that is costly: a thread spinning at a barrier keeps its
// core while its partner, descheduled by another process, cannot get back onto one. With one busy
// process beside sph_bench on 2 cores (dambreak, frames 200-400, four runs each), the default took
// regular to 11-19 ms a step and gaze to 6-12 ms; GOMP_SPINCOUNT=1000 9-10 and 4.6-5 ms; passive
// waiting 9-10 and 4-4.7 ms. On a quiet machine the bounded spin cost nothing measurable, while
// passive waiting made the gaze method's adaptive step (a few short parallel passes, each then
// waking a sleeping thread) 3.5x slower. Of the counts tried, 3,000 and 10,000 were slower under
// load (gaze/regular 0.54-0.65), 300 slower when quiet (adaptive step 0.14-0.18 against 0.08 ms).
// Hence a bounded spin of 1,000 by default; the environment still decides.
#pragma once

#include <string>

namespace sph {

// The spin count the programs set when the environment names no wait policy.
inline constexpr const char* kDefaultOmpSpinCount = "1000";

// True when the environment already says how OpenMP threads wait (OMP_WAIT_POLICY or
// GOMP_SPINCOUNT is set).
bool ompWaitPolicyGiven();

// How this process's threads wait, as the environment says: "OMP_WAIT_POLICY=passive",
// "GOMP_SPINCOUNT=1000" (both when both are set), or "libgomp default". For reports.
std::string ompWaitDescription();

// Call first in main(), before anything starts a thread. When the environment names no wait
// policy, sets GOMP_SPINCOUNT to kDefaultOmpSpinCount and re-executes the program in place (same
// process id, same arguments): libgomp reads its wait policy once, as it loads, before main(), so
// no running program can change its own. Returns when the policy was already given, or when the
// re-execution fails (the program then runs with libgomp's default, and says so on stderr).
void applyDefaultOmpWaitPolicy(char** argv);

}  // namespace sph
