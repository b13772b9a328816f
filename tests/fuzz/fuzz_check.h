/// @file
/// @brief Shared by the fuzz targets: a property check that makes libFuzzer (or the replay driver)
/// report a crash with the reason, and catching only the errors a reader documents.
#pragma once

#include <cstdio>
#include <cstdlib>

/// A property every input must keep (a finite value, a value in its range, a round trip). A
/// failure aborts, which libFuzzer reports as a crash and keeps the input.
#define VDFX_FUZZ_CHECK(cond)                                                               \
  do {                                                                                      \
    if (!(cond)) {                                                                          \
      std::fprintf(stderr, "%s:%d: fuzz property failed: %s\n", __FILE__, __LINE__, #cond); \
      std::abort();                                                                         \
    }                                                                                       \
  } while (false)
