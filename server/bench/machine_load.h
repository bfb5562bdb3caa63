// What else the machine did while a benchmark ran: the CPU time of other processes and the time
// the hypervisor took from this virtual machine's CPUs (steal), both in cores (1.0 = one CPU busy
// the whole time). On a shared 2-core machine a method's timings move with these, so sph_bench
// records them with every scene, and a reader can tell a quiet matrix from a busy one.
#pragma once

#include <cstdint>
#include <string>

namespace bench {

// The machine-wide counters of /proc/stat's "cpu" line, in clock ticks.
struct CpuTicks {
  std::uint64_t busy = 0;   // user + nice + system + irq + softirq (user includes guest time)
  std::uint64_t steal = 0;  // taken by the hypervisor for other guests
};

// Parses the "cpu ..." (all CPUs) line of /proc/stat. False when the line is not one.
bool parseCpuLine(const std::string& line, CpuTicks& out);

// One moment: the machine's counters, this process's CPU time (all threads) and the wall clock.
struct CpuSnapshot {
  bool valid = false;  // false where /proc/stat cannot be read (not Linux)
  CpuTicks ticks;
  double self_cpu_s = 0.0;
  double wall_s = 0.0;  // steady clock
};

CpuSnapshot takeCpuSnapshot();

struct MachineLoad {
  bool known = false;
  double other_cores = 0.0;  // CPU time of other processes per second of wall time
  double steal_cores = 0.0;  // stolen CPU time per second of wall time
};

// The load between two snapshots; `ticks_per_s` is the kernel's clock tick rate (sysconf
// _SC_CLK_TCK). Unknown when either snapshot is invalid or no time passed. Other processes' time
// is the machine's busy time less this process's; clamped at 0 (the tick counters are coarser
// than getrusage's).
MachineLoad loadBetween(const CpuSnapshot& start, const CpuSnapshot& end, double ticks_per_s);
MachineLoad loadBetween(const CpuSnapshot& start, const CpuSnapshot& end);

// "0.05 cores in other processes, 0.00 stolen", or "unknown".
std::string describe(const MachineLoad& load);

}  // namespace bench
