/// @file
/// @brief Swapchain images as GL textures made in the app's context, and reading them back.
#pragma once

#include "tests/openxr_runtime/capture.h"
#include "tests/openxr_runtime/runtime.h"

namespace vdfx::test_runtime {

/// Makes the swapchain's textures (the app's context must be current).
void create_swapchain_textures(Swapchain& sc, std::uint32_t image_count);
void delete_swapchain_textures(Swapchain& sc);

/// Reads `rect` of one array layer of one image as the headset would show it (8-bit sRGB RGBA,
/// top row first), leaving the app's GL state as it was.
CapturedImage read_back(const Swapchain& sc, std::uint32_t image, std::uint32_t array_index,
                        const XrRect2Di& rect);

}  // namespace vdfx::test_runtime
