// Where the tests find the checkout, their data, their output folder and the programs they
// start. A source that CMake generates for each test binary defines these functions
// (vdfx_test_paths in cmake/vdfx_test_paths.cmake), so no test's compile line names the checkout:
// a compiler cache (ccache with CCACHE_BASEDIR) then shares test objects between checkouts.
#pragma once

namespace vdfx::test_paths {

const char* source_dir();            ///< the repository root
const char* test_data_dir();         ///< tests/data
const char* test_output_dir();       ///< the test binary's output folder in the build tree
const char* binary();                ///< the vdfx executable
const char* fault_so();              ///< tests/fault/fault_inject.c, built as a shared library
const char* openxr_test_data_dir();  ///< tests/openxr/data
const char* hello_xr();              ///< Debian's hello_xr, or "" where it is not installed
const char* test_runtime_library();  ///< the simulated OpenXR runtime
const char* xf86vidmode_shim();      ///< the XF86VidMode shim for Xvfb

}  // namespace vdfx::test_paths

#define VDFX_SOURCE_DIR (::vdfx::test_paths::source_dir())
#define VDFX_TEST_DATA_DIR (::vdfx::test_paths::test_data_dir())
#define VDFX_TEST_OUTPUT_DIR (::vdfx::test_paths::test_output_dir())
#define VDFX_BINARY (::vdfx::test_paths::binary())
#define VDFX_FAULT_SO (::vdfx::test_paths::fault_so())
#define VDFX_OPENXR_TEST_DATA_DIR (::vdfx::test_paths::openxr_test_data_dir())
#define VDFX_HELLO_XR (::vdfx::test_paths::hello_xr())
#define VDFX_TEST_RUNTIME_LIBRARY (::vdfx::test_paths::test_runtime_library())
#define VDFX_XF86VIDMODE_SHIM (::vdfx::test_paths::xf86vidmode_shim())
