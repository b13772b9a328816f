#include <iostream>

#include "app/commands.h"

namespace vdfx::app {

int cmd_validate(const Args&) {
  std::cerr << "vdfx validate: not implemented yet\n";
  return kExitInternal;
}

}  // namespace vdfx::app
