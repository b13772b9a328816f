// Placeholder translation unit so the io library exists before its first real source lands.
namespace vdfx::io {}
