/// @file
/// @brief resolve_sidecar_target: an existing --sidecar-out is added to, replaced only with
/// --force, and held locked while the command works.
#include "io/sidecar_target.h"

#include <system_error>

#include "io/input_error.h"

namespace vdfx::io {

namespace fs = std::filesystem;

namespace {

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);
}

std::string count_text(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::size_t keyframe_count(const Sidecar& s) {
  std::size_t n = 0;
  for (const auto& t : s.effects) n += t.keyframes.size();
  for (const auto& f : s.flares) n += f.keyframes.size();
  for (const auto& g : s.grains) n += g.keyframes.size();
  return n;
}

SidecarTarget resolve_sidecar_target(const SidecarOptions& o,
                                     const std::vector<NamedInput>& other_inputs,
                                     const std::string& command) {
  check_output_is_not_input("--sidecar-out", o.out, other_inputs);
  const fs::path out = resolve_output_path(o.out);
  check_not_locked_by_another(out, "--sidecar-out");
  std::error_code ec;
  const bool exists = fs::exists(out, ec);
  SidecarTarget t;
  if (o.in) {
    t.base = *o.in;
    if (exists && !same_file(*o.in, out)) {
      if (!o.force)
        throw InputError("--sidecar-out " + o.out.string() +
                         ": the file exists and would be replaced by --sidecar-in " +
                         o.in->string() +
                         " with the new keyframes; to add to it, name it as --sidecar-in (the "
                         "same file may be both), or pass --force to replace it");
      t.replaces_out = true;
    }
  } else if (exists) {
    if (o.force)
      t.replaces_out = true;
    else {
      t.base = o.out;
      t.adds_to_out = true;
    }
  }
  // Held from here until the result is written: an editor opened meanwhile opens it read-only.
  // Best effort: where no lock can be made (a full disk, a folder not there yet) the write at
  // the end reports what is wrong with the place, as it did before locks.
  std::optional<FileLock::Result> taken;
  try {
    taken = FileLock::acquire(out, command);
  } catch (const InputError&) {
    return t;
  }
  if (taken->held_by) check_not_locked_by_another(out, "--sidecar-out");  // it came first
  t.lock = std::move(taken->lock);
  return t;
}

Sidecar read_sidecar_base(const SidecarTarget& target, Sidecar fresh) {
  if (!target.base) return fresh;
  if (!target.adds_to_out) return read_sidecar(*target.base);
  try {
    return read_sidecar(*target.base);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + "\n--sidecar-out " + target.base->string() +
                     " exists and is not a sidecar vdfx can add to; pass --force to replace it");
  }
}

std::string sidecar_target_note(const SidecarTarget& target, const fs::path& out,
                                const Sidecar& before) {
  if (target.replaces_out) return "replaced " + out.string() + " (--force)";
  if (!target.adds_to_out) return "";
  const std::size_t effects = before.effects.size() + before.flares.size() + before.grains.size();
  return "added to the existing " + out.string() + " (it had " +
         count_text(effects, "effect", "effects") + ", " +
         count_text(keyframe_count(before), "keyframe", "keyframes") + ")";
}

}  // namespace vdfx::io
