/// @file
/// @brief Shared checks of the sidecar extension tests (flare, grain): a broken-document case
/// with the pointer and reason it must be reported with, and the exact round trip.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "io/sidecar.h"
#include "io/sidecar_validate.h"
#include "tests/test_files.h"

namespace vdfx::io::test {

/// A valid document changed by `mutate` must be reported at `pointer` with `message` in it.
struct BrokenCase {
  const char* name;
  std::function<void(nlohmann::json&)> mutate;
  const char* pointer;
  const char* message;
};

inline void PrintTo(const BrokenCase& c, std::ostream* os) {
  *os << c.name;
}

/// Success when `valid` changed by the case is reported as the case says; else every problem that
/// was reported.
inline ::testing::AssertionResult reports_as_expected(const char* valid, const BrokenCase& c) {
  nlohmann::json j = nlohmann::json::parse(valid);
  c.mutate(j);
  std::vector<Problem> problems;
  parse_sidecar(j, "f.vdfx.json", problems);
  std::string all;
  for (const Problem& p : problems) {
    if (p.pointer == c.pointer && p.message.find(c.message) != std::string::npos)
      return ::testing::AssertionSuccess();
    all += p.to_string() + "\n";
  }
  return ::testing::AssertionFailure()
         << "expected at " << c.pointer << ": " << c.message << "\ngot:\n"
         << all;
}

/// The sidecar validates as a document, write -> read gives it back equal, and write -> read ->
/// write gives the same bytes (files in `dir`).
inline void expect_exact_round_trip(const Sidecar& s, const std::filesystem::path& dir) {
  std::vector<Problem> problems;
  parse_sidecar(to_json(s), "mem", problems);
  ASSERT_TRUE(problems.empty()) << problems[0].to_string();
  write_sidecar(dir / "a.vdfx.json", s);
  const Sidecar back = read_sidecar(dir / "a.vdfx.json");
  EXPECT_EQ(back, s);
  write_sidecar(dir / "b.vdfx.json", back);
  EXPECT_EQ(test_files::slurp(dir / "a.vdfx.json"), test_files::slurp(dir / "b.vdfx.json"));
}

}  // namespace vdfx::io::test
