#include "cli/cli_conventions.h"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <regex>
#include <sstream>

namespace cli {
namespace {

// CLI11's own formatter shows a disabling flag as "--no-panel{false}" and validators in its
// internal notation; this one shows the names a user types and the type or accepted values only.
class PlainFormatter : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* opt, bool is_positional) const override {
    if (is_positional) return opt->get_name(true, false);
    std::string names;
    for (const std::string& s : opt->get_snames()) names += (names.empty() ? "-" : ", -") + s;
    for (const std::string& l : opt->get_lnames()) names += (names.empty() ? "--" : ", --") + l;
    return names;
  }
};

std::string programName(const CLI::App& app) {
  const std::string& name = app.get_name();
  return name.empty() ? std::string("program") : name;
}

std::string shortNumber(double v) {
  std::ostringstream out;
  out << v;  // default stream precision: 0.001, 1000, 86400 (no trailing zeros)
  return out.str();
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

const char* version() { return SPH_VERSION; }

void prepare(CLI::App& app, const std::string& program, const std::string& extra_exit_codes) {
  app.name(program);
  app.formatter(std::make_shared<PlainFormatter>());
  app.get_formatter()->column_width(34);
  app.set_version_flag("--version", program + " " + SPH_VERSION, "Print the version and exit");
  app.footer("Exit codes: 0 success; 1 the run failed (a file, a socket, the simulation); 2 usage error" +
             (extra_exit_codes.empty() ? std::string() : "; " + extra_exit_codes) + ".");
}

std::string usageMessage(const CLI::ParseError& error) {
  std::string what = error.what();
  // "The following argument(s) was/were not expected: --bogus"
  for (const char* prefix :
       {"The following argument was not expected: ", "The following arguments were not expected: "}) {
    if (startsWith(what, prefix)) return "unknown option or argument: " + what.substr(std::string(prefix).size());
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
    // "--scene: 1 required TEXT missing" -> "--scene needs a value"
    const auto colon = what.find(':');
    if (colon != std::string::npos && what.find("missing") != std::string::npos) {
      return what.substr(0, colon) + " needs a value";
    }
  }
  // A value outside a name list (CLI::CheckedTransformer): "--render: Check nosuch value in
  // {fluid->0,particles->1} OR {0,1} FAILED" -> "--render: 'nosuch' is not one of fluid, particles".
  static const std::regex checked(R"(^(--?[\w-]+): Check (.*) value in \{([^}]*)\}.* FAILED$)");
  if (std::smatch m; std::regex_match(what, m, checked)) {
    std::string names;
    std::stringstream entries(m[3].str());
    for (std::string entry; std::getline(entries, entry, ',');) {
      names += (names.empty() ? "" : ", ") + entry.substr(0, entry.find("->"));
    }
    return m[1].str() + ": '" + m[2].str() + "' is not one of " + names;
  }
  if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr) {
    const std::string prefix = " is required";
    if (what.size() > prefix.size() && what.compare(what.size() - prefix.size(), prefix.size(), prefix) == 0) {
      return what.substr(0, what.size() - prefix.size()) + " is missing";
    }
  }
  return what;
}

namespace {

// The first command-line word that looks like an option ("--name", "--name=value", "-x") and is
// none of the app's; "" when every one is known.
std::string firstUnknownOption(const CLI::App& app, int argc, char** argv) {
  for (int k = 1; k < argc; ++k) {
    const std::string word = argv[k];
    if (word.size() < 2 || word[0] != '-' || word == "--") continue;
    if (std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.') continue;  // a negative number
    const std::string name = word.substr(0, word.find('='));
    if (app.get_option_no_throw(name) == nullptr) return name;
  }
  return {};
}

}  // namespace

std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);  // stdout, 0
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::RequiredError& e) {
    // CLI11 checks what is required before what is unknown: a mistyped option would read as a
    // missing argument.
    if (const std::string unknown = firstUnknownOption(app, argc, argv); !unknown.empty()) {
      return usageError(app, "unknown option or argument: " + unknown);
    }
    return usageError(app, usageMessage(e));
  } catch (const CLI::ParseError& e) {
    return usageError(app, usageMessage(e));
  }
  return std::nullopt;
}

int usageError(const CLI::App& app, const std::string& message) {
  const std::string name = programName(app);
  std::fprintf(stderr, "%s: %s (see %s --help)\n", name.c_str(), message.c_str(), name.c_str());
  return kExitUsage;
}

namespace {

// A validator of numbers: `accepts` says which; the error says so and quotes the text.
CLI::Validator numberCheck(std::function<bool(double)> accepts, const std::string& expected,
                           const std::string& description) {
  return CLI::Validator(
      [accepts = std::move(accepts), expected](std::string& text) -> std::string {
        double v = 0.0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !accepts(v)) return expected + ", got '" + text + "'";
        return {};
      },
      description);
}

}  // namespace

CLI::Validator range(double lo, double hi) {
  return numberCheck([lo, hi](double v) { return v >= lo && v <= hi; },
                     "expected a number from " + shortNumber(lo) + " to " + shortNumber(hi),
                     "NUMBER " + shortNumber(lo) + ".." + shortNumber(hi));
}

CLI::Validator nonNegative() {
  return numberCheck([](double v) { return std::isfinite(v) && v >= 0.0; }, "expected a number >= 0", "NUMBER >= 0");
}

CLI::Validator positive() {
  return numberCheck([](double v) { return std::isfinite(v) && v > 0.0; }, "expected a number > 0", "NUMBER > 0");
}

void logToStderr() {
  // Unnamed and unregistered, like the default logger it replaces: lines read as before.
  auto logger = std::make_shared<spdlog::logger>("", std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
  logger->set_level(spdlog::get_level());
  spdlog::set_default_logger(logger);
}

}  // namespace cli
