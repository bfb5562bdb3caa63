// How the project's programs' OpenMP threads wait for each other at the end of a parallel loop: a
// decision of each program about its own process, not of the simulation library.
//
// libgomp's default spins for up to 300,000 pause loops before it sleeps, longer than most of a
// step's phases. On a shared machine that is costly: a thread spinning at a barrier keeps its
// core while its partner, descheduled by another process, cannot get back onto one. Passive
// waiting avoids that but makes every short parallel pass (the adaptive step has several) wake a
// sleeping thread. A bounded spin of 1,000 was the best of the counts measured, quiet and under
// load (docs/performance.md); the environment still decides.
#pragma once

#include <string>

namespace process {

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

}  // namespace process
