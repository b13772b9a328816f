/// @file
/// @brief Start-up of commands that need no video library (docs/architecture.md, "Start-up"):
/// wall time of a whole `vdfx validate` / `vdfx --help` process (spawn to exit) against
/// `/bin/true` spawned the same way in the same run (counter "ms_over_true": the difference of the
/// means). The target is 25 ms for `vdfx validate` of a small sidecar.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <string>
#include <vector>

#include "tests/support/test_paths.h"

extern char** environ;

namespace {

double g_true_ms = 0;

/// Spawns `argv` with stdout and stderr closed, waits, returns the wall time in ms.
double run_ms(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ) == 0) waitpid(pid, nullptr, 0);
  posix_spawn_file_actions_destroy(&fa);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void measure(benchmark::State& state, const std::vector<std::string>& args, bool is_peer) {
  double total = 0;
  for (auto _ : state) total += run_ms(args);
  const double ms = total / static_cast<double>(state.iterations());
  if (is_peer)
    g_true_ms = ms;
  else if (g_true_ms > 0)
    state.counters["ms_over_true"] = ms - g_true_ms;
}

void BM_StartTrue(benchmark::State& state) {
  measure(state, {"/bin/true"}, true);
}
void BM_StartValidate(benchmark::State& state) {
  measure(state,
          {VDFX_BINARY, "validate", std::string(VDFX_SOURCE_DIR) + "/app/demo/interior.vdfx.json"},
          false);
}
void BM_StartHelp(benchmark::State& state) {
  measure(state, {VDFX_BINARY, "--help"}, false);
}

}  // namespace

BENCHMARK(BM_StartTrue)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(100);
BENCHMARK(BM_StartValidate)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(100);
BENCHMARK(BM_StartHelp)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(100);
