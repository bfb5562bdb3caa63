#include "process/omp_wait.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace process {

bool ompWaitPolicyGiven() {
  return std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr;
}

std::string ompWaitDescription() {
  std::string out;
  for (const char* name : {"OMP_WAIT_POLICY", "GOMP_SPINCOUNT"}) {
    if (const char* value = std::getenv(name)) {
      if (!out.empty()) out += ", ";
      out += std::string(name) + "=" + value;
    }
  }
  return out.empty() ? "libgomp default" : out;
}

void applyDefaultOmpWaitPolicy(char** argv) {
  if (ompWaitPolicyGiven()) return;
  if (setenv("GOMP_SPINCOUNT", kDefaultOmpSpinCount, 0) != 0) return;
  // /proc/self/exe, not argv[0]: the program may have been found on PATH or started by a
  // relative path from another directory.
  execv("/proc/self/exe", argv);
  std::fprintf(stderr, "note: could not re-execute with GOMP_SPINCOUNT=%s (%s); running with libgomp's default wait\n",
               kDefaultOmpSpinCount, std::strerror(errno));
}

}  // namespace process
