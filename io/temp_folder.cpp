/// @file
/// @brief TempFolder: mkdtemp, then remove_all of that folder only.
#include "io/temp_folder.h"

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "io/input_error.h"

namespace vdfx::io {

TempFolder::TempFolder(const std::string& prefix) {
  std::error_code ec;
  std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec) dir = "/tmp";
  const std::string pattern = (dir / (prefix + "-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  if (::mkdtemp(name.data()) == nullptr)
    throw InputError("cannot make a work folder in " + dir.string() + " (" + std::strerror(errno) +
                     ")");
  path_ = name.data();
}

TempFolder::~TempFolder() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace vdfx::io
