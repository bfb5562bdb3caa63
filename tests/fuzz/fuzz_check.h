// What the fuzz targets share: a property check that stops the run like a crash does, so libFuzzer
// saves the input. An exception escaping a target is a finding too (libFuzzer reports it as a
// deadly signal), which is why each target catches exactly the error type its decoder documents.
#pragma once

#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(condition)                                                                     \
  do {                                                                                            \
    if (!(condition)) {                                                                           \
      std::fprintf(stderr, "fuzz property failed: %s (%s:%d)\n", #condition, __FILE__, __LINE__); \
      std::abort();                                                                               \
    }                                                                                             \
  } while (0)
