/// @file
/// @brief Thin entry point: everything lives in the vdfx_app library so tests can drive it.
#include "app/commands.h"

int main(int argc, char** argv) {
  return vdfx::app::run_main(vdfx::app::Args(argv + 1, argv + argc));
}
