/// @file
/// @brief The runtime's registry (handle lookup), its failure report and its struct checks.
#include <openxr/openxr_reflection.h>

#include <cstdio>
#include <cstring>

#include "tests/openxr_runtime/capture.h"
#include "tests/openxr_runtime/runtime.h"

namespace vdfx::test_runtime {

std::mutex& runtime_mutex() {
  static std::mutex m;
  return m;
}

std::unique_ptr<Instance>& live_instance() {
  static std::unique_ptr<Instance> instance;
  return instance;
}

Session::~Session() = default;

Instance* find_instance(XrInstance h) {
  Instance* i = live_instance().get();
  return h != XR_NULL_HANDLE && to_handle<XrInstance>(i) == h ? i : nullptr;
}

Session* find_session(XrSession h) {
  Instance* i = live_instance().get();
  if (!i || !i->session || h == XR_NULL_HANDLE) return nullptr;
  return to_handle<XrSession>(i->session.get()) == h ? i->session.get() : nullptr;
}

Space* find_space(XrSpace h) {
  Instance* i = live_instance().get();
  if (!i || !i->session) return nullptr;
  for (const auto& s : i->session->spaces) {
    if (to_handle<XrSpace>(s.get()) == h) return s.get();
  }
  return nullptr;
}

Swapchain* find_swapchain(XrSwapchain h) {
  Instance* i = live_instance().get();
  if (!i || !i->session) return nullptr;
  for (const auto& s : i->session->swapchains) {
    if (to_handle<XrSwapchain>(s.get()) == h) return s.get();
  }
  return nullptr;
}

ActionSet* find_action_set(XrActionSet h) {
  Instance* i = live_instance().get();
  if (!i) return nullptr;
  for (const auto& s : i->action_sets) {
    if (!s->destroyed && to_handle<XrActionSet>(s.get()) == h) return s.get();
  }
  return nullptr;
}

Action* find_action(XrAction h) {
  Instance* i = live_instance().get();
  if (!i) return nullptr;
  for (const auto& set : i->action_sets) {
    for (const auto& a : set->actions) {
      if (!a->destroyed && to_handle<XrAction>(a.get()) == h) return a.get();
    }
  }
  return nullptr;
}

XrResult fail(const char* function, XrResult result, const std::string& message) {
  std::fprintf(stderr, "vdfx-test-runtime: %s: %s (%s)\n", function, message.c_str(),
               result_name(result).c_str());
  std::fflush(stderr);
  return result;
}

XrResult check_struct(const char* function, const char* name, const void* s,
                      XrStructureType expected,
                      std::initializer_list<XrStructureType> allowed_next) {
  if (!s) return fail(function, XR_ERROR_VALIDATION_FAILURE, std::string(name) + " is null");
  const auto* base = static_cast<const XrBaseInStructure*>(s);
  if (base->type != expected) {
    return fail(function, XR_ERROR_VALIDATION_FAILURE,
                std::string(name) + "->type is " + structure_type_name(base->type) + ", expected " +
                    structure_type_name(expected));
  }
  int depth = 0;
  for (const XrBaseInStructure* n = base->next; n; n = n->next) {
    bool allowed = false;
    for (const XrStructureType t : allowed_next) allowed = allowed || n->type == t;
    if (!allowed) {
      return fail(function, XR_ERROR_VALIDATION_FAILURE,
                  std::string(name) + "'s next chain holds " + structure_type_name(n->type) +
                      ", which does not extend " + structure_type_name(expected) +
                      " in this runtime");
    }
    if (++depth > 32) {
      return fail(function, XR_ERROR_VALIDATION_FAILURE,
                  std::string(name) + "'s next chain is longer than 32 (a loop?)");
    }
  }
  return XR_SUCCESS;
}

#define VDFX_ENUM_NAME_CASE(name, value) \
  case name: return #name;

std::string result_name(XrResult r) {
  switch (r) { XR_LIST_ENUM_XrResult(VDFX_ENUM_NAME_CASE) default : break; }
  return (r >= 0 ? "XR_UNKNOWN_SUCCESS_" : "XR_UNKNOWN_FAILURE_") + std::to_string(r);
}

std::string structure_type_name(XrStructureType t) {
  switch (t) { XR_LIST_ENUM_XrStructureType(VDFX_ENUM_NAME_CASE) default : break; }
  return "XR_UNKNOWN_STRUCTURE_TYPE_" + std::to_string(t);
}

std::string session_state_name(XrSessionState s) {
  switch (s) { XR_LIST_ENUM_XrSessionState(VDFX_ENUM_NAME_CASE) default : break; }
  return "XR_UNKNOWN_SESSION_STATE_" + std::to_string(s);
}

#undef VDFX_ENUM_NAME_CASE

XrResult two_call_string(const char* function, std::uint32_t capacity, std::uint32_t* count,
                         char* buffer, const std::string& text) {
  if (!count) return fail(function, XR_ERROR_VALIDATION_FAILURE, "the count output is null");
  *count = static_cast<std::uint32_t>(text.size() + 1);
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < text.size() + 1) return XR_ERROR_SIZE_INSUFFICIENT;
  if (!buffer) return fail(function, XR_ERROR_VALIDATION_FAILURE, "the buffer is null");
  std::memcpy(buffer, text.c_str(), text.size() + 1);
  return XR_SUCCESS;
}

}  // namespace vdfx::test_runtime
