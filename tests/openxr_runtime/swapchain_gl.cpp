/// @file
/// @brief Swapchains: formats, GL textures made in the app's context (XrSwapchainImageOpenGLKHR),
/// the acquire / wait / release order (spec 10.1), and reading an image back for the output
/// folder without disturbing the app's GL state.
#include "tests/openxr_runtime/swapchain_gl.h"

#include <algorithm>
#include <cmath>

#include "tests/openxr_runtime/entry_points.h"
#include "tests/openxr_runtime/gl_context.h"

namespace vdfx::test_runtime {
namespace {

/// External format and type for glTexImage (when glTexStorage is missing) by internal format.
std::pair<GLenum, GLenum> upload_format(GLenum internal) {
  switch (internal) {
    case GL_RGBA16F: return {GL_RGBA, GL_HALF_FLOAT};
    case GL_RGB10_A2: return {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV};
    case GL_R11F_G11F_B10F: return {GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV};
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32F: return {GL_DEPTH_COMPONENT, GL_FLOAT};
    case GL_DEPTH24_STENCIL8: return {GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
    case GL_DEPTH32F_STENCIL8: return {GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV};
    default: return {GL_RGBA, GL_UNSIGNED_BYTE};
  }
}

GLenum binding_query(GLenum target) {
  return target == GL_TEXTURE_2D_ARRAY ? GL_TEXTURE_BINDING_2D_ARRAY : GL_TEXTURE_BINDING_2D;
}

/// The sRGB encoding (IEC 61966-2-1) of a 16-bit normalised linear value, by table: a linear
/// swapchain is read back as 16-bit values (exact for 8- and 10-bit formats, float ones clamped
/// to [0, 1] as a display would), so 65536 entries cover every input.
const std::array<std::uint8_t, 65536>& srgb_table() {
  static const auto table = [] {
    std::array<std::uint8_t, 65536> t{};
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double x = static_cast<double>(i) / 65535.0;
      const double e = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
      t[i] = static_cast<std::uint8_t>(std::lround(e * 255.0));
    }
    return t;
  }();
  return table;
}

/// The pack state glGetTexImage reads, saved, set to tight rows, and put back.
class PackState {
 public:
  PackState() {
    for (std::size_t i = 0; i < kNames.size(); ++i) glGetIntegerv(kNames[i], &saved_[i]);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &buffer_);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    for (std::size_t i = 0; i < kNames.size(); ++i) {
      glPixelStorei(kNames[i], kNames[i] == GL_PACK_ALIGNMENT ? 1 : 0);
    }
  }
  ~PackState() {
    for (std::size_t i = 0; i < kNames.size(); ++i) glPixelStorei(kNames[i], saved_[i]);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(buffer_));
  }
  PackState(const PackState&) = delete;
  PackState& operator=(const PackState&) = delete;

 private:
  static constexpr std::array<GLenum, 7> kNames{
      GL_PACK_ALIGNMENT,    GL_PACK_ROW_LENGTH,  GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
      GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES, GL_PACK_SWAP_BYTES};
  std::array<GLint, 7> saved_{};
  GLint buffer_ = 0;
};

}  // namespace

void create_swapchain_textures(Swapchain& sc, std::uint32_t image_count) {
  GLint previous = 0;
  glGetIntegerv(binding_query(sc.target), &previous);
  GLint unpack = 0;
  glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  const bool storage = epoxy_gl_version() >= 42 || epoxy_has_gl_extension("GL_ARB_texture_storage");
  const auto internal = static_cast<GLenum>(sc.format.gl_format);
  sc.textures.assign(image_count, 0);
  glGenTextures(static_cast<GLsizei>(image_count), sc.textures.data());
  for (const GLuint tex : sc.textures) {
    glBindTexture(sc.target, tex);
    const auto w = static_cast<GLsizei>(sc.width), h = static_cast<GLsizei>(sc.height);
    const auto levels = static_cast<GLsizei>(sc.mip_count);
    if (storage && sc.target == GL_TEXTURE_2D) {
      glTexStorage2D(sc.target, levels, internal, w, h);
    } else if (storage) {
      glTexStorage3D(sc.target, levels, internal, w, h, static_cast<GLsizei>(sc.array_size));
    } else {
      const auto [format, type] = upload_format(internal);
      for (GLint level = 0; level < levels; ++level) {
        const GLsizei lw = std::max(1, w >> level), lh = std::max(1, h >> level);
        if (sc.target == GL_TEXTURE_2D) {
          glTexImage2D(sc.target, level, static_cast<GLint>(internal), lw, lh, 0, format, type,
                       nullptr);
        } else {
          glTexImage3D(sc.target, level, static_cast<GLint>(internal), lw, lh,
                       static_cast<GLsizei>(sc.array_size), 0, format, type, nullptr);
        }
      }
    }
    glTexParameteri(sc.target, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(sc.target, GL_TEXTURE_MIN_FILTER,
                    levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(sc.target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }
  glBindTexture(sc.target, static_cast<GLuint>(previous));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack));
}

void delete_swapchain_textures(Swapchain& sc) {
  if (sc.textures.empty()) return;
  glDeleteTextures(static_cast<GLsizei>(sc.textures.size()), sc.textures.data());
  sc.textures.clear();
}

namespace {

/// Reads `rect` of layer `layer` of a texture (`width` x `height`, `layers` deep) as the headset
/// would show it, leaving the app's GL state as it was.
CapturedImage read_texture(GLenum target, GLuint texture, std::uint32_t width, std::uint32_t height,
                           std::uint32_t layers, std::uint32_t layer, bool srgb,
                           const XrRect2Di& rect) {
  GLint previous = 0;
  glGetIntegerv(binding_query(target), &previous);
  const PackState pack;
  glBindTexture(target, texture);
  const std::size_t layer_pixels = std::size_t{width} * height;
  CapturedImage out;
  out.width = rect.extent.width;
  out.height = rect.extent.height;
  out.rgba.resize(std::size_t(out.width) * out.height * 4);
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint16_t> shorts;
  // sRGB swapchains hold display values already: read their bytes. Every other format holds
  // linear light for the compositor: read it and encode it as the display would.
  if (srgb) {
    bytes.resize(layer_pixels * layers * 4);
    glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    out.encoding = "stored";
  } else {
    shorts.resize(layer_pixels * layers * 4);
    glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_SHORT, shorts.data());
    out.encoding = "linear-to-srgb";
  }
  const auto& table = srgb_table();
  glBindTexture(target, static_cast<GLuint>(previous));
  // GL's rows go up from the bottom; the PNG's go down from the top.
  for (int y = 0; y < out.height; ++y) {
    const std::size_t src_row = std::size_t(rect.offset.y) + std::size_t(out.height - 1 - y);
    for (int x = 0; x < out.width; ++x) {
      const std::size_t src =
          (layer * layer_pixels + src_row * width + std::size_t(rect.offset.x) + std::size_t(x)) *
          4;
      std::uint8_t* dst = &out.rgba[(std::size_t(y) * out.width + std::size_t(x)) * 4];
      for (int c = 0; c < 4; ++c) {
        if (srgb) {
          dst[c] = bytes[src + std::size_t(c)];
        } else {
          const std::uint16_t v = shorts[src + std::size_t(c)];
          dst[c] = c < 3 ? table[v] : static_cast<std::uint8_t>((v * 255u + 32767u) / 65535u);
        }
      }
    }
  }
  return out;
}

}  // namespace

CapturedImage read_back(const Swapchain& sc, std::uint32_t image, std::uint32_t array_index,
                        const XrRect2Di& rect) {
  return read_texture(sc.target, sc.textures.at(image), sc.width, sc.height, sc.array_size,
                      array_index, sc.format.srgb, rect);
}

GLuint copy_region(const Swapchain& sc, std::uint32_t image, std::uint32_t array_index,
                   const XrRect2Di& rect) {
  const bool can = epoxy_gl_version() >= 43 || (epoxy_has_gl_extension("GL_ARB_copy_image") &&
                                                epoxy_has_gl_extension("GL_ARB_texture_storage"));
  if (!can) return 0;
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  GLuint copy = 0;
  glGenTextures(1, &copy);
  glBindTexture(GL_TEXTURE_2D, copy);
  glTexStorage2D(GL_TEXTURE_2D, 1, static_cast<GLenum>(sc.format.gl_format), rect.extent.width,
                 rect.extent.height);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
  glCopyImageSubData(sc.textures.at(image), sc.target, 0, rect.offset.x, rect.offset.y,
                     static_cast<GLint>(array_index), copy, GL_TEXTURE_2D, 0, 0, 0, 0,
                     rect.extent.width, rect.extent.height, 1);
  return copy;
}

void resolve_copy(CapturedView& view) {
  if (!view.pending_copy) return;
  const XrRect2Di whole{{0, 0}, view.rect.extent};
  view.image = read_texture(
      GL_TEXTURE_2D, view.pending_copy, static_cast<std::uint32_t>(view.rect.extent.width),
      static_cast<std::uint32_t>(view.rect.extent.height), 1, 0, view.format_srgb, whole);
  drop_copy(view);
}

void drop_copy(CapturedView& view) {
  if (!view.pending_copy) return;
  glDeleteTextures(1, &view.pending_copy);
  view.pending_copy = 0;
}

namespace api {
namespace {

/// SteamVR's habit, on request: the runtime's own GL context is current after the call.
void maybe_switch_context(Session& s) {
  if (s.switch_context) GlContextScope scope(s);
}

XrResult check_create_info(const char* fn, const XrSwapchainCreateInfo& info) {
  constexpr XrSwapchainCreateFlags known =
      XR_SWAPCHAIN_CREATE_PROTECTED_CONTENT_BIT | XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT;
  if (info.createFlags & ~known)
    return fail(fn, XR_ERROR_VALIDATION_FAILURE, "unknown createFlags");
  if (info.createFlags & XR_SWAPCHAIN_CREATE_PROTECTED_CONTENT_BIT) {
    return fail(fn, XR_ERROR_FEATURE_UNSUPPORTED, "no protected content");
  }
  if (info.width == 0 || info.height == 0 || info.arraySize == 0 || info.mipCount == 0 ||
      info.faceCount == 0 || info.sampleCount == 0) {
    return fail(fn, XR_ERROR_VALIDATION_FAILURE,
                "width, height, sampleCount, faceCount, arraySize and mipCount must be at least 1");
  }
  if (info.sampleCount != 1) {
    return fail(
        fn, XR_ERROR_FEATURE_UNSUPPORTED,
        "sampleCount " + std::to_string(info.sampleCount) + ": maxSwapchainSampleCount is 1");
  }
  if (info.faceCount != 1) {
    return fail(fn, XR_ERROR_FEATURE_UNSUPPORTED, "no cube swapchains (faceCount must be 1)");
  }
  if (info.width > kMaxSwapchainSize || info.height > kMaxSwapchainSize) {
    return fail(
        fn, XR_ERROR_FEATURE_UNSUPPORTED,
        "larger than maxSwapchainImageWidth/Height (" + std::to_string(kMaxSwapchainSize) + ")");
  }
  const auto max_levels =
      static_cast<std::uint32_t>(std::floor(std::log2(std::max(info.width, info.height)))) + 1;
  if (info.mipCount > max_levels) {
    return fail(fn, XR_ERROR_FEATURE_UNSUPPORTED, "mipCount larger than the full chain");
  }
  return XR_SUCCESS;
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateSwapchainFormats(XrSession session, uint32_t capacity,
                                                           uint32_t* count, int64_t* formats) {
  constexpr const char* fn = "xrEnumerateSwapchainFormats";
  return guarded(fn, [&] {
    if (!find_session(session)) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const auto& offered = live_instance()->config.formats;
    return two_call(fn, capacity, count, formats, offered.size(), [&](int64_t& f, std::size_t i) {
      f = offered[i].gl_format;
      return XR_SUCCESS;
    });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrCreateSwapchain(XrSession session,
                                                 const XrSwapchainCreateInfo* info,
                                                 XrSwapchain* swapchain) {
  constexpr const char* fn = "xrCreateSwapchain";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    XrResult r = check_struct(fn, "createInfo", info, XR_TYPE_SWAPCHAIN_CREATE_INFO);
    if (XR_FAILED(r)) return r;
    if (!swapchain) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "swapchain is null");
    if (s->state == XR_SESSION_STATE_LOSS_PENDING) return XR_ERROR_SESSION_LOST;
    const SwapchainFormat* format = nullptr;
    for (const auto& f : live_instance()->config.formats) {
      if (f.gl_format == info->format) format = &f;
    }
    if (!format) {
      return fail(fn, XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED,
                  "format " + std::to_string(info->format) +
                      " is not one xrEnumerateSwapchainFormats lists");
    }
    r = check_create_info(fn, *info);
    if (XR_FAILED(r)) return r;
    auto sc = std::make_unique<Swapchain>();
    sc->create_flags = info->createFlags;
    sc->usage = info->usageFlags;
    sc->format = *format;
    sc->width = info->width;
    sc->height = info->height;
    sc->array_size = info->arraySize;
    sc->mip_count = info->mipCount;
    sc->target = info->arraySize > 1 ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D;
    {
      GlContextScope scope(*s);
      create_swapchain_textures(*sc, (info->createFlags & XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT)
                                         ? 1
                                         : kSwapchainImageCount);
    }
    *swapchain = to_handle<XrSwapchain>(sc.get());
    s->swapchains.push_back(std::move(sc));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrDestroySwapchain(XrSwapchain swapchain) {
  constexpr const char* fn = "xrDestroySwapchain";
  return guarded(fn, [&] {
    Swapchain* sc = find_swapchain(swapchain);
    if (!sc) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown swapchain");
    Session& s = *live_instance()->session;
    {
      GlContextScope scope(s);
      delete_swapchain_textures(*sc);
    }
    std::erase_if(s.swapchains, [&](const auto& p) { return p.get() == sc; });
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateSwapchainImages(XrSwapchain swapchain, uint32_t capacity,
                                                          uint32_t* count,
                                                          XrSwapchainImageBaseHeader* images) {
  constexpr const char* fn = "xrEnumerateSwapchainImages";
  return guarded(fn, [&] {
    Swapchain* sc = find_swapchain(swapchain);
    if (!sc) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown swapchain");
    auto* gl_images = reinterpret_cast<XrSwapchainImageOpenGLKHR*>(images);
    return two_call(fn, capacity, count, gl_images, sc->textures.size(),
                    [&](XrSwapchainImageOpenGLKHR& image, std::size_t i) {
                      const XrResult r =
                          check_struct(fn, "images[i]", &image, XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR);
                      if (XR_FAILED(r)) return r;
                      image.image = sc->textures[i];
                      return XR_SUCCESS;
                    });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrAcquireSwapchainImage(XrSwapchain swapchain,
                                                       const XrSwapchainImageAcquireInfo* info,
                                                       uint32_t* index) {
  constexpr const char* fn = "xrAcquireSwapchainImage";
  return guarded(fn, [&] {
    Swapchain* sc = find_swapchain(swapchain);
    if (!sc) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown swapchain");
    if (info) {
      const XrResult r =
          check_struct(fn, "acquireInfo", info, XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO);
      if (XR_FAILED(r)) return r;
    }
    if (!index) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "index is null");
    const bool is_static = sc->create_flags & XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT;
    if (is_static && sc->static_acquired) {
      return fail(fn, XR_ERROR_CALL_ORDER_INVALID, "a static swapchain is acquired once only");
    }
    if (sc->acquired.size() >= sc->textures.size()) {
      return fail(fn, XR_ERROR_CALL_ORDER_INVALID, "every image is acquired already");
    }
    *index = sc->next_image;
    sc->acquired.push_back(sc->next_image);
    sc->next_image = (sc->next_image + 1) % static_cast<std::uint32_t>(sc->textures.size());
    sc->static_acquired = is_static;
    maybe_switch_context(*live_instance()->session);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrWaitSwapchainImage(XrSwapchain swapchain,
                                                    const XrSwapchainImageWaitInfo* info) {
  constexpr const char* fn = "xrWaitSwapchainImage";
  return guarded(fn, [&] {
    Swapchain* sc = find_swapchain(swapchain);
    if (!sc) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown swapchain");
    const XrResult r = check_struct(fn, "waitInfo", info, XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
    if (XR_FAILED(r)) return r;
    if (sc->waited >= sc->acquired.size()) {
      return fail(fn, XR_ERROR_CALL_ORDER_INVALID, "no acquired image waits to be waited on");
    }
    ++sc->waited;  // the runtime never holds an image: it is ready at once
    maybe_switch_context(*live_instance()->session);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrReleaseSwapchainImage(XrSwapchain swapchain,
                                                       const XrSwapchainImageReleaseInfo* info) {
  constexpr const char* fn = "xrReleaseSwapchainImage";
  return guarded(fn, [&] {
    Swapchain* sc = find_swapchain(swapchain);
    if (!sc) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown swapchain");
    if (info) {
      const XrResult r =
          check_struct(fn, "releaseInfo", info, XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO);
      if (XR_FAILED(r)) return r;
    }
    if (sc->waited == 0) {
      return fail(fn, XR_ERROR_CALL_ORDER_INVALID, "no waited image to release");
    }
    sc->released = sc->acquired.front();
    sc->acquired.pop_front();
    --sc->waited;
    maybe_switch_context(*live_instance()->session);
    return XR_SUCCESS;
  });
}

}  // namespace api
}  // namespace vdfx::test_runtime
