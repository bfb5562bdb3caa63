// Command-line conventions of every program (README "Exit codes"): usage errors are one line on
// stderr that names the option and what it accepts, exit code 2; --help and --version print to
// stdout and exit 0; logs go to stderr so stdout carries only data and reports.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the run failed (a file, a socket, the simulation)
inline constexpr int kExitUsage = 2;    // the command line is wrong

// The project's version (CMake's project(VERSION)).
const char* version();

// Adds --version, the exit-code footer (`extra_exit_codes` lines such as "3  timed out" come after
// 0, 1 and 2) and a help formatter that shows options the way a user types them.
void prepare(CLI::App& app, const std::string& program, const std::string& extra_exit_codes = "");

// Parses; an exit code when the program should stop now (help/version: 0; usage error: 2, after one
// line "PROGRAM: MESSAGE (see PROGRAM --help)" on stderr).
std::optional<int> parse(CLI::App& app, int argc, char** argv);

// Prints the usage-error line for checks made after parsing; returns kExitUsage.
int usageError(const CLI::App& app, const std::string& message);

// The one-line message for a CLI11 parse error, in our words (exposed for the unit tests).
std::string usageMessage(const CLI::ParseError& error);

// A number in [lo, hi]; the error says so in plain numbers ("expected a number from 0.001 to 1000").
CLI::Validator range(double lo, double hi);

// A number >= 0, or > 0; the error says so in one line ("expected a number >= 0, got '-5'").
CLI::Validator nonNegative();
CLI::Validator positive();

// Every spdlog message to stderr (the default logger writes to stdout).
void logToStderr();

}  // namespace cli
