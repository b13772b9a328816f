// Placeholder translation unit so the xr library exists before its first real source lands.
namespace vdfx::xr {}
