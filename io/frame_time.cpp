/// @file
/// @brief Exact time <-> frame conversion with 128-bit intermediates.
#include "io/frame_time.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace vdfx::io {

namespace {
// t_ns * num reaches 10 h * 1e9 * 60000 = 2e18 and more at higher rates: past int64 territory.
__extension__ typedef __int128 i128;

i128 floor_div(i128 a, i128 b) {
  i128 q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

void check(Rational fps) {
  if (fps.num <= 0 || fps.den <= 0)
    throw std::invalid_argument("frame rate " + std::to_string(fps.num) + "/" +
                                std::to_string(fps.den) + " is not positive");
}
}  // namespace

Rational fps_to_rational(double fps) {
  if (!(fps > 0.0) || !std::isfinite(fps))
    throw std::invalid_argument("frame rate " + std::to_string(fps) + " is not a positive number");
  // Convergents h/k of the continued fraction of fps.
  long double x = fps;
  std::int64_t h0 = 1, h1 = 0, k0 = 0, k1 = 1;  // h_{-1}, h_{-2}, k_{-1}, k_{-2}
  Rational best{static_cast<std::int64_t>(std::llround(fps)), 1};
  for (int i = 0; i < 64; ++i) {
    const long double a_ld = std::floor(x);
    if (a_ld > 1e12L) break;
    const auto a = static_cast<std::int64_t>(a_ld);
    const std::int64_t h = a * h0 + h1, k = a * k0 + k1;
    if (k > 1000000) break;
    best = {h, k};
    if (std::fabs(static_cast<double>(h) / static_cast<double>(k) - fps) <= 1e-9 * fps) break;
    h1 = h0;
    h0 = h;
    k1 = k0;
    k0 = k;
    const long double frac = x - a_ld;
    if (frac <= 0.0L) break;
    x = 1.0L / frac;
  }
  if (best.num <= 0) best = {1, 1};
  return best;
}

std::int64_t frame_at_time(std::int64_t t_ns, Rational fps) {
  check(fps);
  const i128 n = (static_cast<i128>(t_ns) * 2 + 1) * fps.num;
  const i128 d = static_cast<i128>(fps.den) * 2'000'000'000;
  return static_cast<std::int64_t>(floor_div(n, d));
}

std::int64_t frame_start_ns(std::int64_t frame, Rational fps) {
  check(fps);
  const i128 n = static_cast<i128>(frame) * fps.den * 2'000'000'000 + fps.num;
  return static_cast<std::int64_t>(floor_div(n, static_cast<i128>(fps.num) * 2));
}

std::int64_t playback_frame(std::int64_t t_ns, Rational fps, std::int64_t frames, bool loop) {
  if (frames <= 0) throw std::invalid_argument("playback_frame: no frames");
  const std::int64_t f = frame_at_time(t_ns, fps);
  if (loop) return ((f % frames) + frames) % frames;
  return f < 0 ? 0 : (f >= frames ? frames - 1 : f);
}

}  // namespace vdfx::io
