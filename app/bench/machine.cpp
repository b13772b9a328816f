/// @file
/// @brief Reads what the report header says about the machine.
#include "app/bench/machine.h"

#include <ctime>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <utility>

namespace vdfx::app::bench {

void read_load(double out[3]) {
  std::ifstream in("/proc/loadavg");
  for (int i = 0; i < 3; ++i)
    if (!(in >> out[i])) out[i] = kNaN;
}

namespace {

std::string value_of(const std::string& line) {
  const auto colon = line.find(':');
  if (colon == std::string::npos) return {};
  const auto start = line.find_first_not_of(" \t", colon + 1);
  return start == std::string::npos ? std::string() : line.substr(start);
}

}  // namespace

Machine describe_machine() {
  Machine m;
  std::ifstream in("/proc/cpuinfo");
  std::string line, physical_id;
  std::set<std::pair<std::string, std::string>> cores;  // (physical id, core id)
  for (; std::getline(in, line);) {
    if (line.rfind("model name", 0) == 0 && m.cpu.empty()) m.cpu = value_of(line);
    if (line.rfind("physical id", 0) == 0) physical_id = value_of(line);
    if (line.rfind("core id", 0) == 0) cores.insert({physical_id, value_of(line)});
  }
  if (m.cpu.empty()) m.cpu = "unknown CPU";
  m.logical_cpus = static_cast<int>(std::thread::hardware_concurrency());
  m.physical_cores = cores.empty() ? m.logical_cpus : static_cast<int>(cores.size());
#ifdef NDEBUG
  m.build = "optimised";
#else
  m.build = "debug (assertions on)";
#endif
#if defined(__AVX2__) && defined(__FMA__)
  m.build += ", AVX2 + FMA (x86-64-v3)";
#else
  m.build += ", baseline x86-64";
#endif
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  m.date_utc = date;
  read_load(m.load_start);
  return m;
}

}  // namespace vdfx::app::bench
