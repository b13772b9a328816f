/// @file
/// @brief The OpenXR backend's swapchains: one per eye and one per panel, filled by a copy pass
/// that writes what the chosen format needs (xr/openxr/openxr_format.h).
#include <algorithm>
#include <unordered_set>

#include "xr/openxr/gl/openxr_runtime_impl.h"
#include "xr/render/gl_context.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {
namespace {

// The copy: texel for texel (source and image have one size), clamped to [0, 1] here, the very
// end of vdfx's pipeline. u_mode 0: as it is (an sRGB image: the runtime decodes). 1: decoded to
// linear light (a linear image). 2: a premultiplied panel into an sRGB image: the runtime decodes
// each stored channel, so the stored value is encode(decode(colour) * alpha), whose decoding is
// the premultiplied linear colour (storing colour * alpha would darken the panel's soft edges).
constexpr const char* kCopyFragment = R"(
in vec2 v_uv;
out vec4 frag;
uniform sampler2D u_src;
uniform int u_flip;
uniform int u_mode;
uniform int u_opaque;
vec3 to_linear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}
vec3 to_srgb(vec3 l) {
  return mix(l * 12.92, 1.055 * pow(l, vec3(1.0 / 2.4)) - 0.055, greaterThan(l, vec3(0.0031308)));
}
void main() {
  ivec2 size = textureSize(u_src, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (u_flip != 0) p.y = size.y - 1 - p.y;
  vec4 c = clamp(texelFetch(u_src, p, 0), 0.0, 1.0);
  if (u_opaque != 0) c.a = 1.0;
  if (u_mode != 0) {
    vec3 straight = c.a > 0.0 ? min(c.rgb / c.a, vec3(1.0)) : vec3(0.0);
    vec3 linear = to_linear(straight) * c.a;
    c.rgb = u_mode == 1 ? linear : to_srgb(linear);
  }
  frag = c;
}
)";

}  // namespace

OpenXrSwapchain OpenXrRuntime::Impl::create_swapchain(std::int64_t format, int width, int height) {
  auto ci = xr_struct<XrSwapchainCreateInfo>(XR_TYPE_SWAPCHAIN_CREATE_INFO);
  ci.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
  ci.format = format;
  ci.sampleCount = 1;
  ci.width = static_cast<std::uint32_t>(width);
  ci.height = static_cast<std::uint32_t>(height);
  ci.faceCount = 1;
  ci.arraySize = 1;  // no texture arrays: one swapchain per eye (docs/openxr.md, quirks)
  ci.mipCount = 1;
  OpenXrSwapchain c;
  c.width = width;
  c.height = height;
  XrResult r = xrCreateSwapchain(session, &ci, &c.handle);
  restore_context();
  xr_check(r, "xrCreateSwapchain");
  std::uint32_t n = 0;
  xr_check(xrEnumerateSwapchainImages(c.handle, 0, &n, nullptr), "xrEnumerateSwapchainImages");
  std::vector<XrSwapchainImageOpenGLKHR> images(
      n, xr_struct<XrSwapchainImageOpenGLKHR>(XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR));
  r = xrEnumerateSwapchainImages(c.handle, n, &n,
                                 reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data()));
  restore_context();
  xr_check(r, "xrEnumerateSwapchainImages");
  c.fbos.resize(n);
  glGenFramebuffers(static_cast<GLsizei>(n), c.fbos.data());
  for (std::uint32_t i = 0; i < n; ++i) {
    c.images.push_back(images[i].image);
    glBindFramebuffer(GL_FRAMEBUFFER, c.fbos[i]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, images[i].image, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw GlError("OpenXR swapchain image " + std::to_string(i) + " (" + gl_format_name(format) +
                    ") cannot be rendered to");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return c;
}

void OpenXrRuntime::Impl::destroy_swapchain(OpenXrSwapchain& c) {
  if (!c.handle) return;
  if (window) restore_context();
  if (!c.fbos.empty()) glDeleteFramebuffers(static_cast<GLsizei>(c.fbos.size()), c.fbos.data());
  xrDestroySwapchain(c.handle);
  c = OpenXrSwapchain();
}

void OpenXrRuntime::Impl::copy_into(OpenXrSwapchain& c, GLuint src, bool flip, bool premultiplied) {
  if (!copy_program.id()) {
    copy_program = GlProgram::build("openxr_copy", fullscreen_vertex_source(), kCopyFragment);
    glGenVertexArrays(1, &copy_vao);
  }
  auto ai = xr_struct<XrSwapchainImageAcquireInfo>(XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO);
  XrResult r = xrAcquireSwapchainImage(c.handle, &ai, &c.acquired);
  restore_context();
  xr_check(r, "xrAcquireSwapchainImage");
  c.held = true;
  auto wi = xr_struct<XrSwapchainImageWaitInfo>(XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
  wi.timeout = XR_INFINITE_DURATION;
  r = xrWaitSwapchainImage(c.handle, &wi);
  restore_context();
  xr_check(r, "xrWaitSwapchainImage");

  const bool srgb = swapchain_info.format.srgb;
  glBindFramebuffer(GL_FRAMEBUFFER, c.fbos.at(c.acquired));
  glViewport(0, 0, c.width, c.height);
  glDisable(GL_FRAMEBUFFER_SRGB);  // the values are written as the shader gives them
  glDisable(GL_BLEND);
  copy_program.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, src);
  glUniform1i(copy_program.uniform("u_src"), 0);
  glUniform1i(copy_program.uniform("u_flip"), flip ? 1 : 0);
  glUniform1i(copy_program.uniform("u_mode"), !srgb ? 1 : premultiplied ? 2 : 0);
  glUniform1i(copy_program.uniform("u_opaque"), premultiplied ? 0 : 1);
  glBindVertexArray(copy_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  auto ri = xr_struct<XrSwapchainImageReleaseInfo>(XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO);
  r = xrReleaseSwapchainImage(c.handle, &ri);
  restore_context();
  c.held = false;
  xr_check(r, "xrReleaseSwapchainImage");
}

void OpenXrRuntime::submit_quads(std::span<const QuadLayer> quads) {
  Impl& m = *impl_;
  // The projection layer takes one of the runtime's layers; panels beyond its limit are left out.
  const std::size_t room = m.info.max_layers > 1 ? m.info.max_layers - 1 : 0;
  // A texture shown by several quads (both hands' pointer dots) is copied once: every layer
  // naming a swapchain shows its last released image.
  std::unordered_set<unsigned> copied;
  for (const QuadLayer& q : quads) {
    if (!q.texture || m.quad_layers.size() >= room) continue;
    GLint w = 0, h = 0;
    glBindTexture(GL_TEXTURE_2D, q.texture);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (w < 1 || h < 1) continue;
    OpenXrSwapchain& c = m.quad_chains[q.texture];
    if (c.width != w || c.height != h) {
      m.destroy_swapchain(c);
      c = m.create_swapchain(m.swapchain_info.format.format, w, h);
    }
    if (copied.insert(q.texture).second) m.copy_into(c, q.texture, true, true);
    auto layer = xr_struct<XrCompositionLayerQuad>(XR_TYPE_COMPOSITION_LAYER_QUAD);
    // Premultiplied alpha (UNPREMULTIPLIED_ALPHA_BIT unset), blended over the layers below.
    layer.layerFlags = XR_COMPOSITION_LAYER_BLEND_TEXTURE_SOURCE_ALPHA_BIT;
    layer.space = q.space == ReferenceSpace::View ? m.view : m.local;
    layer.eyeVisibility = XR_EYE_VISIBILITY_BOTH;
    layer.subImage.swapchain = c.handle;
    layer.subImage.imageRect = {{0, 0}, {w, h}};
    layer.pose.position = {static_cast<float>(q.pose.position.x),
                           static_cast<float>(q.pose.position.y),
                           static_cast<float>(q.pose.position.z)};
    const glm::dquat o = glm::normalize(q.pose.orientation);
    layer.pose.orientation = {static_cast<float>(o.x), static_cast<float>(o.y),
                              static_cast<float>(o.z), static_cast<float>(o.w)};
    layer.size = {static_cast<float>(q.size_m.x()), static_cast<float>(q.size_m.y())};
    m.quad_layers.push_back(layer);
  }
}

}  // namespace vdfx::xr
