#include <iostream>

#include "app/commands.h"

namespace vdfx::app {

int cmd_eval(const Args&) {
  std::cerr << "vdfx eval: not implemented yet\n";
  return kExitInternal;
}

}  // namespace vdfx::app
