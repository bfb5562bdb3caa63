// The machine-load figures sph_bench writes with every scene (bench/machine_load.h): /proc/stat's
// "cpu" line parsed, other processes' time as the machine's busy time less ours, steal apart.
#include <gtest/gtest.h>

#include <time.h>

#include <chrono>
#include <cmath>

#include "bench/machine_load.h"

namespace {

TEST(MachineLoad, ParsesTheAllCpuLine) {
  bench::CpuTicks ticks;
  // user nice system idle iowait irq softirq steal guest guest_nice
  ASSERT_TRUE(bench::parseCpuLine("cpu  4705 150 1120 16250 520 30 45 7 0 0", ticks));
  EXPECT_EQ(ticks.busy, 4705u + 150u + 1120u + 30u + 45u);
  EXPECT_EQ(ticks.steal, 7u);
  EXPECT_FALSE(bench::parseCpuLine("cpu0 4705 150 1120 16250 520 30 45 7 0 0", ticks)) << "one CPU, not all";
  EXPECT_FALSE(bench::parseCpuLine("cpu  4705 150 1120", ticks)) << "too short";
  EXPECT_FALSE(bench::parseCpuLine("intr 12345", ticks));
}

bench::CpuSnapshot snapshot(std::uint64_t busy, std::uint64_t steal, double self_s, double wall_s) {
  bench::CpuSnapshot s;
  s.valid = true;
  s.ticks.busy = busy;
  s.ticks.steal = steal;
  s.self_cpu_s = self_s;
  s.wall_s = wall_s;
  return s;
}

TEST(MachineLoad, OtherProcessesGetTheBusyTimeThatIsNotOurs) {
  // Over 2 s at 100 ticks a second: 3 s busy on the machine, 1 s of it ours, 0.2 s stolen.
  const bench::MachineLoad load =
      bench::loadBetween(snapshot(1000, 50, 4.0, 10.0), snapshot(1300, 70, 5.0, 12.0), 100.0);
  ASSERT_TRUE(load.known);
  EXPECT_DOUBLE_EQ(load.other_cores, 1.0);
  EXPECT_DOUBLE_EQ(load.steal_cores, 0.1);
  EXPECT_EQ(bench::describe(load), "1.00 cores in other processes, 0.10 stolen");

  // Ticks are coarser than getrusage: ours may exceed the machine's count; never below zero.
  EXPECT_DOUBLE_EQ(bench::loadBetween(snapshot(1000, 0, 4.0, 10.0), snapshot(1100, 0, 5.2, 11.0), 100.0).other_cores,
                   0.0);
}

TEST(MachineLoad, UnknownWithoutTwoReadingsOrTime) {
  bench::CpuSnapshot unreadable = snapshot(1300, 70, 5.0, 12.0);
  unreadable.valid = false;
  EXPECT_FALSE(bench::loadBetween(snapshot(1000, 50, 4.0, 10.0), unreadable, 100.0).known);
  EXPECT_FALSE(bench::loadBetween(snapshot(1000, 50, 4.0, 10.0), snapshot(1300, 70, 5.0, 10.0), 100.0).known);
  EXPECT_FALSE(bench::loadBetween(snapshot(1000, 50, 4.0, 10.0), snapshot(900, 70, 5.0, 12.0), 100.0).known)
      << "counters that went backwards";
  EXPECT_EQ(bench::describe(bench::MachineLoad{}), "unknown");
}

// The kernel's own count of this process's CPU time (the clock getrusage reads too).
double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

TEST(MachineLoad, LiveSnapshotsCountOurOwnWorkAsOurs) {
  const bench::CpuSnapshot start = bench::takeCpuSnapshot();
  ASSERT_TRUE(start.valid) << "this project runs on Linux, where /proc/stat exists";
  // 0.3 s of our own CPU time, however long a busy machine takes to give it to us (the wall-clock
  // limit only stops a machine that gives none): it must show as ours, not another process's.
  const double cpu_start = processCpuSeconds();
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  volatile double sink = 0.0;
  while (processCpuSeconds() - cpu_start < 0.3) {
    for (int k = 0; k < 100000; ++k) sink = sink + 1.0;
    ASSERT_LT(std::chrono::steady_clock::now(), give_up) << "no CPU time in two minutes";
  }
  const bench::CpuSnapshot end = bench::takeCpuSnapshot();
  EXPECT_GE(end.self_cpu_s - start.self_cpu_s, 0.25);
  const bench::MachineLoad load = bench::loadBetween(start, end);
  ASSERT_TRUE(load.known);
  // The figures are per second of the snapshots' own wall clock: finite whatever the machine does
  // (their units are checked on fixed snapshots above).
  EXPECT_TRUE(std::isfinite(load.other_cores));
  EXPECT_TRUE(std::isfinite(load.steal_cores));
}

}  // namespace
