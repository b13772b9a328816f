/// @file
/// @brief run_publish: checks, the staged folder, the atomic exchange (docs/publish.md).
#include "app/publish/publish_request.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <nlohmann/json.hpp>
#include <system_error>

#include "app/cli/layout_options.h"
#include "app/publish/publish_assets.h"
#include "app/publish/publish_lights.h"
#include "app/publish/publish_video.h"
#include "io/durable.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/input_file.h"
#include "io/output_path.h"
#include "io/sidecar_validate.h"
#include "io/video_layout.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

/// What publish writes beside the page: it marks a folder as one publish may replace.
constexpr const char* kManifest = "player.json";
constexpr const char* kManifestFormat = "vdfx.publish";

/// More than any player.json publish writes (a few KiB): a larger one is not publish's.
constexpr std::uintmax_t kMaxManifestBytes = std::uintmax_t{1} << 20;

bool is_publish_folder(const fs::path& dir) {
  // Read as an input is (io/input_file.h): a regular file only, never a pipe waited on.
  std::string why;
  const std::optional<std::string> text =
      io::try_read_input_file(dir / kManifest, kMaxManifestBytes, "a publish manifest", why);
  if (!text) return false;
  try {
    const nlohmann::json j = nlohmann::json::parse(*text);
    return j.is_object() && j.value("format", "") == kManifestFormat;
  } catch (const std::exception&) {
    return false;
  }
}

/// OUT may be missing, an empty folder, or a folder an earlier publish wrote: anything else is
/// refused, so a mistyped --out never replaces a folder of the user's.
void check_out_folder(const PublishRequest& r) {
  io::check_output_is_not_input("--out", r.out, {{"VIDEO", r.video}, {"--sidecar", r.sidecar}});
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(r.out, ec);
  if (ec || st.type() == fs::file_type::not_found) return;
  const std::string name = r.out.string();
  if (st.type() == fs::file_type::symlink)
    throw io::InputError(name + ": --out is a symbolic link; name the folder itself");
  if (st.type() != fs::file_type::directory)
    throw io::InputError(name + ": --out names a folder to write, and this is a file");
  if (fs::is_empty(r.out, ec) || is_publish_folder(r.out)) return;
  throw io::InputError(name + ": the folder exists and is not one vdfx publish wrote (no " +
                       kManifest + "); choose a new --out or empty it first");
}

/// The sidecar, validated as `vdfx validate` does; its problems are the message (exit 1).
io::Sidecar checked_sidecar(const fs::path& path) {
  io::SidecarReport report = io::validate_sidecar_file(path);
  if (report.ok()) return std::move(*report.sidecar);
  std::string text = report.to_string();
  while (!text.empty() && text.back() == '\n') text.pop_back();
  const std::size_t n = report.problems.size();
  throw io::InputError(text + "\n" + path.string() + ": " + std::to_string(n) +
                       (n == 1 ? " problem" : " problems"));
}

bool browser_container(const fs::path& video) {
  std::string e = video.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e == ".mp4" || e == ".m4v" || e == ".webm";
}

/// The video's codec; refuses what browsers do not play unless the request transcodes.
std::string checked_codec(const PublishRequest& r, const io::VideoProperties& props) {
  const std::string codec = props.is_still ? "a still image" : props.codec;
  if (r.transcode != Transcode::None) return codec;
  if (!browser_plays(props.codec))
    throw io::InputError(r.video.string() + ": the codec " + (codec.empty() ? "?" : codec) +
                         " does not play in browsers (they play h264, vp8, vp9 and av1); "
                         "publish with --transcode h264 (or vp9)");
  if (!browser_container(r.video))
    throw io::InputError(r.video.string() + ": the container " + r.video.extension().string() +
                         " does not play in every browser (.mp4, .m4v and .webm do); "
                         "publish with --transcode h264 (or vp9)");
  return codec;
}

/// Removes `.NAME.publish-PID` folders in `parent` whose process no longer exists (a publish
/// that was killed or interrupted); a live publish's folder is never touched. Only the names in
/// `parent` are read: nothing else there is opened or walked, and only a folder of that name
/// (not a link, not a file) is removed.
void remove_stale_staging(const fs::path& parent, const std::string& name) {
  const std::string prefix = "." + name + ".publish-";
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(parent, ec)) {
    const std::string n = e.path().filename().string();
    if (!n.starts_with(prefix) || n.size() == prefix.size()) continue;
    if (!e.is_directory(ec) || e.is_symlink(ec)) continue;
    const std::string digits = n.substr(prefix.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH) fs::remove_all(e.path(), ec);
  }
}

/// A temporary sibling of OUT, removed again unless it was put in place.
class StagedFolder {
 public:
  explicit StagedFolder(const fs::path& out) {
    const fs::path abs = fs::absolute(out).lexically_normal();
    const fs::path name = abs.has_filename() ? abs.filename() : abs.parent_path().filename();
    const fs::path parent =
        abs.has_filename() ? abs.parent_path() : abs.parent_path().parent_path();
    path_ = parent / ("." + name.string() + ".publish-" + std::to_string(::getpid()));
    target_ = parent / name;
    remove_stale_staging(parent, name.string());
    std::error_code ec;
    fs::remove_all(path_, ec);
    if (!fs::create_directory(path_, ec))
      throw io::InputError(out.string() + ": cannot create a folder beside it (" + ec.message() +
                           ")");
  }
  ~StagedFolder() {
    std::error_code ec;
    if (!path_.empty()) fs::remove_all(path_, ec);
  }
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;
  const fs::path& path() const { return path_; }
  /// Puts the folder in place: its own files and folders fsynced (a failure keeps the old
  /// folder: io::InputError), then one rename when OUT is missing, else an atomic exchange of the
  /// two names (renameat2 RENAME_EXCHANGE), after which the old folder is removed; then the
  /// parent's entry fsynced, and only that (never what else the parent holds). Returns a warning
  /// when that last fsync failed (the folder is in place, not yet durable), else "".
  std::string commit(const std::string& out_name);

 private:
  fs::path path_, target_;
};

std::string StagedFolder::commit(const std::string& out_name) {
  if (const std::optional<io::SyncFailure> f = io::fsync_written_tree(path_))
    throw io::InputError(out_name + ": the new folder cannot be made durable (fsync of " +
                         f->describe() + "); the old one is kept");
  std::error_code ec;
  const bool exists = fs::exists(fs::symlink_status(target_, ec));
  constexpr unsigned kExchange = 1u << 1;  // RENAME_EXCHANGE (linux/fs.h)
  const long r = exists ? ::syscall(SYS_renameat2, AT_FDCWD, path_.c_str(), AT_FDCWD,
                                    target_.c_str(), kExchange)
                        : ::rename(path_.c_str(), target_.c_str());
  if (r != 0)
    throw io::InputError(out_name + ": cannot put the new folder in place (" +
                         std::strerror(errno) + "); the old one is kept");
  if (!exists) path_.clear();  // the destructor removes the old folder, now at path_
  // The new name is durable once the parent's list of names is: that one folder's entry, as
  // io::write_file_atomic syncs its file's folder. A file system that cannot sync a folder
  // (EINVAL) counts as synced.
  const int err = io::fsync_folder_entry(target_.parent_path());
  if (err == 0 || err == EINVAL) return {};
  return out_name + ": published, but not yet durable: the fsync of its folder " +
         target_.parent_path().string() + " failed (" + std::strerror(err) +
         "); a power cut now could still lose the new folder";
}

}  // namespace

bool browser_plays(const std::string& codec) {
  static const std::array<const char*, 4> kPlayable = {"h264", "vp8", "vp9", "av1"};
  return std::find(kPlayable.begin(), kPlayable.end(), codec) != kPlayable.end();
}

PublishResult run_publish(const PublishRequest& r) {
  check_out_folder(r);
  const io::Sidecar sidecar = checked_sidecar(r.sidecar);
  const io::VideoProperties props = io::open_frame_decoder(r.video, {})->properties();
  const std::string source_codec = checked_codec(r, props);
  PublishResult result;
  result.layout = shown_layout(props, r.layout, &sidecar.video, r.sidecar);
  const PageAssets assets = find_page_assets();
  StagedFolder staged(r.out);
  result.out = r.out;
  PublishedVideo video = publish_video(r, sidecar, staged.path());
  video.layout = result.layout;
  result.video_codec = r.transcode == Transcode::None ? source_codec : video.codec;
  result.transcoded = r.transcode != Transcode::None;
  copy_file_checked(r.sidecar, staged.path() / kPublishedSidecar);
  write_page(assets, staged.path(), page_settings(r, sidecar, video, result.video_codec));
  // Tracked in the video the page plays (after --transcode, the transcoded one): the light is
  // where that video's bright region is, as `vdfx render` of it finds it.
  if (uses_auto_light(sidecar))
    write_text_file(staged.path() / kLightsFile,
                    track_auto_lights(staged.path() / video.file, sidecar).dump(2) + "\n");
  result.left_out = left_out_of(sidecar);
  result.files = folder_listing(staged.path());
  result.warning = staged.commit(r.out.string());
  return result;
}

}  // namespace vdfx::app
