/// @file
/// @brief The frame loop on the virtual clock: xrWaitFrame gives frame k the display time
/// kClockOriginNs + k * period (frame_timing: placeholder frames and a refresh rate change
/// aside; it never waits on the wall clock), xrBeginFrame and xrEndFrame check their order and
/// every submitted layer, and chosen frames are read back.
#include <optional>

#include "tests/openxr_runtime/capture.h"
#include "tests/openxr_runtime/entry_points.h"
#include "tests/openxr_runtime/gl_context.h"
#include "tests/openxr_runtime/session_state.h"
#include "tests/openxr_runtime/swapchain_gl.h"
#include "tests/openxr_runtime/tracking.h"

namespace vdfx::test_runtime::api {
namespace {

constexpr XrCompositionLayerFlags kKnownLayerFlags =
    XR_COMPOSITION_LAYER_CORRECT_CHROMATIC_ABERRATION_BIT |
    XR_COMPOSITION_LAYER_BLEND_TEXTURE_SOURCE_ALPHA_BIT |
    XR_COMPOSITION_LAYER_UNPREMULTIPLIED_ALPHA_BIT;

/// The frame-loop functions' result in a session that is about to be lost.
XrResult frame_result(const Session& s, XrResult ok) {
  return s.state == XR_SESSION_STATE_LOSS_PENDING ? XR_SESSION_LOSS_PENDING : ok;
}

/// What happens on the clock at frame k: LOSS_PENDING at its time, the way out when the script
/// has run out or the frame limit is reached, SYNCHRONIZED once the loop runs.
void advance_states(Instance& inst, Session& s, std::int64_t k) {
  const Config& c = inst.config;
  const std::int64_t script_time = s.now - kClockOriginNs;
  if (c.loss_pending_ns && script_time >= *c.loss_pending_ns &&
      s.state != XR_SESSION_STATE_LOSS_PENDING) {
    set_session_state(inst, s, XR_SESSION_STATE_LOSS_PENDING);
    return;
  }
  if (s.state == XR_SESSION_STATE_LOSS_PENDING) return;
  const bool script_over = inst.script && script_time > inst.script->end_ns();
  const bool frames_over = c.exit_after_frames && k >= *c.exit_after_frames;
  if (script_over || frames_over) begin_exit(inst, s);
  if (s.state == XR_SESSION_STATE_READY) set_session_state(inst, s, XR_SESSION_STATE_SYNCHRONIZED);
}

struct SubImage {
  Swapchain* swapchain = nullptr;
};

XrResult check_sub_image(const char* fn, const std::string& what, const XrSwapchainSubImage& si,
                         SubImage& out) {
  Swapchain* sc = find_swapchain(si.swapchain);
  if (!sc) return fail(fn, XR_ERROR_HANDLE_INVALID, what + ".swapchain is not a swapchain");
  if (!sc->released) {
    return fail(fn, XR_ERROR_LAYER_INVALID,
                what + ".swapchain has no released image (acquire, wait, render, release first)");
  }
  if (sc->format.depth) {
    return fail(fn, XR_ERROR_LAYER_INVALID, what + ".swapchain holds depth, not colour");
  }
  const XrRect2Di& r = si.imageRect;
  if (r.offset.x < 0 || r.offset.y < 0 || r.extent.width <= 0 || r.extent.height <= 0 ||
      std::int64_t(r.offset.x) + r.extent.width > std::int64_t(sc->width) ||
      std::int64_t(r.offset.y) + r.extent.height > std::int64_t(sc->height)) {
    return fail(fn, XR_ERROR_SWAPCHAIN_RECT_INVALID,
                what + ".imageRect is not inside the " + std::to_string(sc->width) + "x" +
                    std::to_string(sc->height) + " swapchain");
  }
  if (si.imageArrayIndex >= sc->array_size) {
    return fail(fn, XR_ERROR_VALIDATION_FAILURE, what + ".imageArrayIndex is beyond arraySize");
  }
  out.swapchain = sc;
  return XR_SUCCESS;
}

/// A view's record; its pixels read now, or (`later`) copied on the GPU to be read at the end.
CapturedView capture_view(const Instance& inst, const Session& s, const Space& space, XrTime time,
                          const XrPosef& pose, const XrSwapchainSubImage& si, const Swapchain& sc,
                          bool later) {
  CapturedView v;
  v.pose = pose;
  if (const auto base = space_pose(inst, s, space, time)) {
    v.pose_in_local = compose(*base, from_xr(pose));
  }
  v.format = sc.format.name;
  v.swapchain_width = sc.width;
  v.swapchain_height = sc.height;
  v.rect = si.imageRect;
  v.array_index = si.imageArrayIndex;
  v.image_index = *sc.released;
  v.format_srgb = sc.format.srgb;
  if (later) v.pending_copy = copy_region(sc, *sc.released, si.imageArrayIndex, si.imageRect);
  if (!v.pending_copy) v.image = read_back(sc, *sc.released, si.imageArrayIndex, si.imageRect);
  return v;
}

XrResult check_projection(const char* fn, const std::string& what,
                          const XrCompositionLayerProjection& p, const Instance& inst,
                          const Session& s, CapturedLayer* out, XrTime time, bool later) {
  if (p.viewCount != 2 || !p.views) {
    return fail(fn, XR_ERROR_VALIDATION_FAILURE,
                what + ".viewCount must be 2 (the stereo view configuration)");
  }
  for (uint32_t v = 0; v < p.viewCount; ++v) {
    const std::string view = what + ".views[" + std::to_string(v) + "]";
    const XrCompositionLayerProjectionView& pv = p.views[v];
    XrResult r = check_struct(fn, view.c_str(), &pv, XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW);
    if (XR_FAILED(r)) return r;
    if (!is_valid_pose(pv.pose)) return fail(fn, XR_ERROR_POSE_INVALID, view + ".pose");
    SubImage si;
    r = check_sub_image(fn, view + ".subImage", pv.subImage, si);
    if (XR_FAILED(r)) return r;
    if (out) {
      CapturedView cv = capture_view(inst, s, *find_space(p.space), time, pv.pose, pv.subImage,
                                     *si.swapchain, later);
      cv.fov = pv.fov;
      out->views.push_back(std::move(cv));
    }
  }
  return XR_SUCCESS;
}

XrResult check_quad(const char* fn, const std::string& what, const XrCompositionLayerQuad& q,
                    const Instance& inst, const Session& s, CapturedLayer* out, XrTime time,
                    bool later) {
  if (q.eyeVisibility != XR_EYE_VISIBILITY_BOTH && q.eyeVisibility != XR_EYE_VISIBILITY_LEFT &&
      q.eyeVisibility != XR_EYE_VISIBILITY_RIGHT) {
    return fail(fn, XR_ERROR_VALIDATION_FAILURE, what + ".eyeVisibility");
  }
  if (!is_valid_pose(q.pose)) return fail(fn, XR_ERROR_POSE_INVALID, what + ".pose");
  SubImage si;
  const XrResult r = check_sub_image(fn, what + ".subImage", q.subImage, si);
  if (XR_FAILED(r)) return r;
  if (out) {
    out->eye_visibility = q.eyeVisibility == XR_EYE_VISIBILITY_BOTH
                              ? "both"
                              : (q.eyeVisibility == XR_EYE_VISIBILITY_LEFT ? "left" : "right");
    out->size = q.size;
    out->views.push_back(capture_view(inst, s, *find_space(q.space), time, q.pose, q.subImage,
                                      *si.swapchain, later));
  }
  return XR_SUCCESS;
}

/// Checks one layer; with `out`, also reads it back (`later`: copies it to read at the end).
XrResult check_layer(const char* fn, std::uint32_t index, const XrCompositionLayerBaseHeader* layer,
                     const Instance& inst, const Session& s, CapturedLayer* out, XrTime time,
                     bool later = false) {
  const std::string what = "frameEndInfo->layers[" + std::to_string(index) + "]";
  if (!layer) return fail(fn, XR_ERROR_LAYER_INVALID, what + " is null");
  if (layer->type != XR_TYPE_COMPOSITION_LAYER_PROJECTION &&
      layer->type != XR_TYPE_COMPOSITION_LAYER_QUAD) {
    return fail(fn, XR_ERROR_LAYER_INVALID,
                what + " is a " + structure_type_name(layer->type) +
                    ": the runtime composes projection and quad layers");
  }
  XrResult r = check_struct(fn, what.c_str(), layer, layer->type);
  if (XR_FAILED(r)) return r;
  if (layer->layerFlags & ~kKnownLayerFlags) {
    return fail(fn, XR_ERROR_VALIDATION_FAILURE, what + ".layerFlags has unknown bits");
  }
  const Space* space = find_space(layer->space);
  if (!space) return fail(fn, XR_ERROR_HANDLE_INVALID, what + ".space is not a space");
  if (out) {
    out->flags = layer->layerFlags;
    out->space = space_name(*space);
  }
  if (layer->type == XR_TYPE_COMPOSITION_LAYER_PROJECTION) {
    if (out) out->type = "projection";
    return check_projection(fn, what, *reinterpret_cast<const XrCompositionLayerProjection*>(layer),
                            inst, s, out, time, later);
  }
  if (out) out->type = "quad";
  return check_quad(fn, what, *reinterpret_cast<const XrCompositionLayerQuad*>(layer), inst, s, out,
                    time, later);
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL xrWaitFrame(XrSession session, const XrFrameWaitInfo* info,
                                           XrFrameState* state) {
  constexpr const char* fn = "xrWaitFrame";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    if (info) {
      const XrResult r = check_struct(fn, "frameWaitInfo", info, XR_TYPE_FRAME_WAIT_INFO);
      if (XR_FAILED(r)) return r;
    }
    const XrResult r = check_struct(fn, "frameState", state, XR_TYPE_FRAME_STATE);
    if (XR_FAILED(r)) return r;
    if (!s->running) return fail(fn, XR_ERROR_SESSION_NOT_RUNNING, "xrBeginSession first");
    Instance& inst = *live_instance();
    const std::int64_t k = s->waits++;
    const FrameTiming timing = frame_timing(inst, *s, k);
    s->now = timing.time;
    advance_states(inst, *s, k);
    state->predictedDisplayTime = s->now;
    state->predictedDisplayPeriod = timing.period_ns;
    state->shouldRender =
        (s->state == XR_SESSION_STATE_VISIBLE || s->state == XR_SESSION_STATE_FOCUSED) ? XR_TRUE
                                                                                       : XR_FALSE;
    return frame_result(*s, XR_SUCCESS);
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrBeginFrame(XrSession session, const XrFrameBeginInfo* info) {
  constexpr const char* fn = "xrBeginFrame";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    if (info) {
      const XrResult r = check_struct(fn, "frameBeginInfo", info, XR_TYPE_FRAME_BEGIN_INFO);
      if (XR_FAILED(r)) return r;
    }
    if (!s->running) return fail(fn, XR_ERROR_SESSION_NOT_RUNNING, "xrBeginSession first");
    if (s->begins >= s->waits) {
      return fail(fn, XR_ERROR_CALL_ORDER_INVALID, "no xrWaitFrame before this xrBeginFrame");
    }
    // A frame begun again before its xrEndFrame is discarded (a success code).
    const XrResult result = s->in_frame ? XR_FRAME_DISCARDED : XR_SUCCESS;
    s->begun_frame = s->waits - 1;
    s->begun_time = s->now;
    s->begins = s->waits;
    s->in_frame = true;
    return frame_result(*s, result);
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrEndFrame(XrSession session, const XrFrameEndInfo* info) {
  constexpr const char* fn = "xrEndFrame";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r = check_struct(fn, "frameEndInfo", info, XR_TYPE_FRAME_END_INFO);
    if (XR_FAILED(r)) return r;
    if (!s->running) return fail(fn, XR_ERROR_SESSION_NOT_RUNNING, "xrBeginSession first");
    if (!s->in_frame) return fail(fn, XR_ERROR_CALL_ORDER_INVALID, "no xrBeginFrame before it");
    if (info->displayTime <= 0) return fail(fn, XR_ERROR_TIME_INVALID, "displayTime <= 0");
    if (info->environmentBlendMode != XR_ENVIRONMENT_BLEND_MODE_OPAQUE) {
      return fail(fn, XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED, "the headset is opaque");
    }
    if (info->layerCount > kMaxLayerCount) {
      return fail(fn, XR_ERROR_LAYER_LIMIT_EXCEEDED, "more than maxLayerCount layers");
    }
    if (info->layerCount > 0 && !info->layers) {
      return fail(fn, XR_ERROR_VALIDATION_FAILURE, "layers is null");
    }
    const Instance& inst = *live_instance();
    for (uint32_t i = 0; i < info->layerCount; ++i) {
      const XrResult lr = check_layer(fn, i, info->layers[i], inst, *s, nullptr, info->displayTime);
      if (XR_FAILED(lr)) return lr;
    }
    const bool capture = s->recorder && s->recorder->wants(s->begun_frame);
    if (capture || s->switch_context) {
      GlContextScope scope(*s);
      if (capture) {
        CapturedFrame frame;
        frame.frame = s->begun_frame;
        frame.display_time = info->displayTime;
        frame.predicted_display_time = s->begun_time;
        const bool later = s->recorder->keeps_last();
        for (uint32_t i = 0; i < info->layerCount; ++i) {
          frame.layers.emplace_back();
          check_layer(fn, i, info->layers[i], inst, *s, &frame.layers.back(), info->displayTime,
                      later);
        }
        if (auto dropped = s->recorder->frame(std::move(frame))) {
          for (auto& layer : dropped->layers) {
            for (auto& view : layer.views) drop_copy(view);
          }
        }
      }
    }
    s->in_frame = false;
    ++s->frames_ended;
    // A frame reached the display: the app is seen, and (no other app here) has input focus.
    if (s->state == XR_SESSION_STATE_SYNCHRONIZED && !s->exit_begun) {
      set_session_state(*live_instance(), *s, XR_SESSION_STATE_VISIBLE);
      set_session_state(*live_instance(), *s, XR_SESSION_STATE_FOCUSED);
    }
    return frame_result(*s, XR_SUCCESS);
  });
}

}  // namespace vdfx::test_runtime::api
