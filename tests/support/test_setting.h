// A setting only the tests have, added to the settings table (sph/param_table.h) for one scope:
// adding a setting is one row, and what reads the table sees it without a line of its own.
#pragma once

#include "sph/param_table.h"

namespace sph_test {

// Another key for foveated_merge_hold_s, with a range of its own, so what sets it can be read back.
inline sph::ParamSpec testOnlySetting() {
  return {"test_only_hold_s",
          nullptr,
          "foveated",
          &sph::AdaptiveConfig::foveated_merge_hold_s,
          0,
          5,
          false,
          false,
          "s",
          "a setting only the tests have"};
}

// Registers the row while it lives, so a failing test leaves the table as it found it.
class ScopedSetting {
 public:
  explicit ScopedSetting(const sph::ParamSpec& row) : key_(row.key) { sph::registerParameter(row); }
  ~ScopedSetting() { sph::unregisterParameter(key_); }
  ScopedSetting(const ScopedSetting&) = delete;
  ScopedSetting& operator=(const ScopedSetting&) = delete;

 private:
  const char* key_;
};

}  // namespace sph_test
