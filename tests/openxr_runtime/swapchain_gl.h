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

/// Copies `rect` of one array layer of one image into a new texture of the same format on the
/// GPU (glCopyImageSubData: no GL state of the app is touched), for a read-back later; 0 when
/// the context cannot (OpenGL before 4.3 without ARB_copy_image and ARB_texture_storage): then
/// read back at once.
GLuint copy_region(const Swapchain& sc, std::uint32_t image, std::uint32_t array_index,
                   const XrRect2Di& rect);

/// Reads a view's pending copy into its image and deletes the copy; drop_copy only deletes it.
void resolve_copy(CapturedView& view);
void drop_copy(CapturedView& view);

}  // namespace vdfx::test_runtime
