#include <iostream>

#include "app/commands.h"

namespace vdfx::app {

int cmd_render(const Args&) {
  std::cerr << "vdfx render: not implemented yet\n";
  return kExitInternal;
}

}  // namespace vdfx::app
