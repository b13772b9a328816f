// Placeholder translation unit so the ui library exists before its first real source lands.
namespace vdfx::ui {}
