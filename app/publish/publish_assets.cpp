/// @file
/// @brief The page's files (see publish_assets.h).
#include "app/publish/publish_assets.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/publish/publish_lights.h"
#include "effects/effect_shaders.h"
#include "effects/flare_shaders.h"
#include "effects/glsl_common.h"
#include "effects/grain.h"
#include "effects/grain_shaders.h"
#include "effects/stereo_layout.h"
#include "effects/video_shaders.h"
#include "io/file_type.h"
#include "io/input_error.h"
#include "io/ycbcr.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
namespace glsl = effects::glsl;
using effects::EffectType;
using effects::shader_bit;

fs::path executable_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path(".") : exe.parent_path();
}

/// "&", "<", ">" and quotes as HTML entities (the title goes into the page's text).
std::string html_escaped(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

/// Effects of the stack that have keyframes (bit i: effect i): the page compiles these in.
unsigned keyed_mask(const io::Sidecar& sidecar) {
  unsigned m = 0;
  for (const effects::EffectTrack& t : sidecar.effects)
    if (!t.keyframes.empty()) m |= shader_bit(t.type);
  return m;
}

/// The shared GLSL as the page compiles it: the ES prelude, then the same text the GL path
/// compiles (xr/render/gl_program.h prepends the desktop prelude instead).
void write_shaders(const fs::path& dir, unsigned mask) {
  fs::create_directory(dir);
  const std::string es = glsl::prelude(glsl::Target::Es300);
  write_text_file(dir / "fullscreen.vert", es + glsl::kFullscreenVertex);
  write_text_file(dir / "video.frag", es + effects::video_layer_fragment_source());
  write_text_file(dir / "blur_1d.frag", es + effects::blur_1d_fragment_source());
  effects::StackShader v;
  v.mask = mask & ~shader_bit(EffectType::Blur);
  write_text_file(dir / "stack.frag", es + effects::stack_fragment_source(v));
  v.blur = effects::StackShader::Blur::FusedVertical;
  write_text_file(dir / "stack_blur.frag", es + effects::stack_fragment_source(v));
  // The layers after the stack (flare.js and grain.js draw them): the flare elements, the shader
  // grain styles.
  write_text_file(dir / "flare.vert", es + effects::flare_vertex_source());
  write_text_file(dir / "flare.frag", es + effects::flare_fragment_source());
  write_text_file(dir / "grain.frag", es + effects::grain_shader_fragment_source());
}

/// What the page needs to convert the decoded planes itself, as the GL path does (the video
/// layer's u_ycbcr path): the subsampling, the chroma siting and the affine map from code values
/// to R'G'B' (io::ycbcr_to_rgb_map, row-major). The page converts only 8-bit 4:2:0 (I420).
nlohmann::ordered_json ycbcr_json(const io::YcbcrInfo& y) {
  const io::AffineMap3 a = io::ycbcr_to_rgb_map(y);
  nlohmann::ordered_json j;
  j["bit_depth"] = y.bit_depth;
  j["log2_chroma"] = {y.log2_chroma_w, y.log2_chroma_h};
  j["chroma_siting"] = {y.chroma_x, y.chroma_y};
  j["full_range"] = y.full_range;
  j["m"] = a.m;
  j["offset"] = a.offset;
  return j;
}

/// The stereo layout as the page reads it: the layout's and the coverage's names as the sidecar
/// writes them, the width of a VR180 image's fade, and each eye's rectangle of the frame
/// (effects::eye_rect; mono: the whole frame for both), so the page never splits a frame itself.
void add_layout_json(nlohmann::ordered_json& video, const PublishedVideo& v) {
  video["layout"] = std::string(effects::stereo_mode_name(v.layout.mode));
  video["coverage"] = v.layout.coverage_deg;
  video["coverage_edge_deg"] = effects::kCoverageEdgeDeg;
  for (const effects::EyeIndex eye : {effects::EyeIndex::Left, effects::EyeIndex::Right}) {
    const effects::PixelRect r = effects::eye_rect(v.layout, eye, v.width, v.height);
    video["eyes"][std::string(effects::eye_index_name(eye))] = {
        {"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height}};
  }
}

}  // namespace

PageAssets find_page_assets() {
  PageAssets a;
  a.page_dir = fs::path(VDFX_SOURCE_DIR) / "app" / "publish" / "page";
  a.wasm_dir = executable_dir() / "wasm";
  if (!fs::is_regular_file(a.page_dir / "index.html"))
    throw std::runtime_error("the page's sources are missing (" + a.page_dir.string() + ")");
  if (!fs::is_regular_file(a.wasm_dir / "vdfx_player.wasm"))
    throw std::runtime_error("the web player's module is missing (" + a.wasm_dir.string() +
                             "/vdfx_player.wasm): build vdfx with -DVDFX_BUILD_WASM=ON");
  return a;
}

PageSettings page_settings(const PublishRequest& r, const io::Sidecar& sidecar,
                           const PublishedVideo& video, const std::string& codec) {
  PageSettings s;
  s.title = r.title.empty() ? r.video.filename().string() : r.title;
  nlohmann::ordered_json& m = s.manifest;
  m["format"] = "vdfx.publish";
  m["version"] = 1;
  m["title"] = s.title;
  // The files under fixed names (publish_video.h), each with its original name beside it.
  m["video"] = {{"file", video.file},     {"name", r.video.filename().string()},
                {"codec", codec},         {"fps", video.fps},
                {"frames", video.frames}, {"width", video.width},
                {"height", video.height}};
  if (video.ycbcr) m["video"]["ycbcr"] = ycbcr_json(*video.ycbcr);
  add_layout_json(m["video"], video);
  m["sidecar"] = kPublishedSidecar;
  m["sidecar_name"] = r.sidecar.filename().string();
  m["stack_mask"] = keyed_mask(sidecar);
  if (uses_auto_light(sidecar)) m["lights"] = kLightsFile;
  m["left_out"] = left_out_of(sidecar);
  return s;
}

void write_page(const PageAssets& a, const fs::path& dir, const PageSettings& s) {
  for (const fs::directory_entry& e : fs::directory_iterator(a.page_dir)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    std::string text = read_asset_text(e.path());
    if (name == "index.html") {
      const std::string key = "{{TITLE}}";
      for (std::size_t at; (at = text.find(key)) != std::string::npos;)
        text.replace(at, key.size(), html_escaped(s.title));
    }
    write_text_file(dir / name, text);
  }
  copy_file_checked(a.wasm_dir / "vdfx_player.js", dir / "vdfx_player.js");
  copy_file_checked(a.wasm_dir / "vdfx_player.wasm", dir / "vdfx_player.wasm");
  write_shaders(dir / "shaders", s.manifest["stack_mask"].get<unsigned>());
  write_text_file(dir / "player.json", s.manifest.dump(2) + "\n");
}

std::vector<std::string> left_out_of(const io::Sidecar& sidecar) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < sidecar.grains.size(); ++i)
    if (effects::is_volumetric(sidecar.grains[i].style))
      out.push_back("grain #" + std::to_string(i + 1) + " (" +
                    std::string(effects::grain_style_name(sidecar.grains[i].style)) + ")");
  return out;
}

std::vector<std::string> folder_listing(const fs::path& dir) {
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path().lexically_relative(dir).generic_string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string read_asset_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (!in) throw io::InputError(path.string() + ": cannot be read");
  return s.str();
}

namespace {

/// A descriptor closed when it goes out of scope.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

/// Writes all of `data`; false with errno set on a failure (a full disk: ENOSPC).
bool write_all(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w == 0) errno = EIO;
    if (w <= 0) return false;
    data += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

}  // namespace

void copy_file_checked(const fs::path& from, const fs::path& to) {
  const auto fail = [&](const std::string& why) {
    throw io::InputError(to.string() + ": cannot copy " + from.string() + " there (" + why + ")");
  };
  // Opened as the readers open an input (io/input_file.h): without waiting on a named pipe that
  // took the file's place, and refused unless it is a regular file.
  Fd in{::open(from.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (in.fd < 0) fail(std::strerror(errno));
  struct stat st {};
  if (::fstat(in.fd, &st) != 0) fail(std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw io::InputError(from.string() + ": is " + io::file_type_name(st.st_mode) +
                         ", not a regular file");
  Fd out{::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666)};
  if (out.fd < 0) fail(std::strerror(errno));
  std::vector<char> buffer(std::size_t{1} << 20);
  for (;;) {
    const ssize_t n = ::read(in.fd, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(std::string("read: ") + std::strerror(errno));
    if (n == 0) break;
    if (!write_all(out.fd, buffer.data(), static_cast<std::size_t>(n))) fail(std::strerror(errno));
  }
  const int fd = out.fd;
  out.fd = -1;
  if (::close(fd) != 0) fail(std::strerror(errno));
}

void write_text_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw io::InputError(path.string() + ": cannot be written");
}

}  // namespace vdfx::app
