#include "bench/machine_load.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace bench {

bool parseCpuLine(const std::string& line, CpuTicks& out) {
  std::istringstream in(line);
  std::string label;
  if (!(in >> label) || label != "cpu") return false;
  // user nice system idle iowait irq softirq steal (guest and guest_nice, when present, are
  // already counted in user and nice).
  std::uint64_t v[8];
  for (auto& x : v) {
    if (!(in >> x)) return false;
  }
  out.busy = v[0] + v[1] + v[2] + v[5] + v[6];
  out.steal = v[7];
  return true;
}

CpuSnapshot takeCpuSnapshot() {
  CpuSnapshot s;
  s.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return s;
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  s.self_cpu_s = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  std::ifstream stat("/proc/stat");
  std::string line;
  if (!std::getline(stat, line)) return s;
  s.valid = parseCpuLine(line, s.ticks);
  return s;
}

MachineLoad loadBetween(const CpuSnapshot& start, const CpuSnapshot& end, double ticks_per_s) {
  MachineLoad load;
  const double wall = end.wall_s - start.wall_s;
  if (!start.valid || !end.valid || !(wall > 0.0) || !(ticks_per_s > 0.0) || end.ticks.busy < start.ticks.busy ||
      end.ticks.steal < start.ticks.steal) {
    return load;
  }
  const double busy_s = static_cast<double>(end.ticks.busy - start.ticks.busy) / ticks_per_s;
  const double steal_s = static_cast<double>(end.ticks.steal - start.ticks.steal) / ticks_per_s;
  const double self_s = end.self_cpu_s - start.self_cpu_s;
  load.known = true;
  load.other_cores = std::max(0.0, busy_s - self_s) / wall;
  load.steal_cores = steal_s / wall;
  return load;
}

MachineLoad loadBetween(const CpuSnapshot& start, const CpuSnapshot& end) {
  return loadBetween(start, end, static_cast<double>(sysconf(_SC_CLK_TCK)));
}

std::string describe(const MachineLoad& load) {
  if (!load.known) return "unknown";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.2f cores in other processes, %.2f stolen", load.other_cores, load.steal_cores);
  return buf;
}

}  // namespace bench
