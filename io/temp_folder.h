/// @file
/// @brief A work folder of vdfx's own in the temporary folder: made new (mkdtemp: never one that
/// was there before, nor a link), and removed with everything in it when it goes out of scope. A
/// fixed name there (NAME-PID) could be a folder or a link someone else left, which the removal
/// would walk.
#pragma once

#include <filesystem>
#include <string>

namespace vdfx::io {

class TempFolder {
 public:
  /// `$TMPDIR/PREFIX-XXXXXX` (std::filesystem::temp_directory_path), mode 0700; io::InputError
  /// naming the temporary folder and the reason when it cannot be made (a full or read-only disk).
  explicit TempFolder(const std::string& prefix);
  ~TempFolder();
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace vdfx::io
