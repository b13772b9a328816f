/// @file
/// @brief SuggestWorker (suggest_worker.h): suggest::suggest_into on a thread.
#include "app/editor/suggest_worker.h"

#include <exception>

namespace vdfx::app {

std::optional<suggest::Kind> suggestion_for(EditTarget target) {
  if (target == effects::EffectType::Exposure) return suggest::Kind::Exposure;
  if (target == effects::EffectType::Saturation) return suggest::Kind::Guide;
  if (target == effects::EffectType::Vignette) return suggest::Kind::Comfort;
  return std::nullopt;
}

std::string suggestion_title(suggest::Kind kind) {
  switch (kind) {
    case suggest::Kind::Exposure: return "Suggest exposure";
    case suggest::Kind::Guide: return "Suggest guidance";
    case suggest::Kind::Comfort: return "Suggest comfort";
  }
  return {};
}

SuggestWorker::SuggestWorker(suggest::SuggestRequest request, io::Sidecar sidecar, bool async)
    : request_(std::move(request)) {
  if (async)
    thread_ = std::thread([this, s = std::move(sidecar)]() mutable { run(std::move(s)); });
  else
    run(std::move(sidecar));
}

SuggestWorker::~SuggestWorker() {
  cancel();
  if (thread_.joinable()) thread_.join();
}

void SuggestWorker::run(io::Sidecar sidecar) {
  SuggestOutcome out;
  try {
    out.report = suggest::suggest_into(request_, sidecar, &progress_);
    out.sidecar = std::move(sidecar);
  } catch (const suggest::Cancelled&) {
    out.cancelled = true;
    out.problem = "cancelled";
  } catch (const std::exception& e) {  // an unreadable video, one that cannot be metered, ...
    out.problem = e.what();
  }
  result_.put(std::move(out));
}

std::optional<SuggestOutcome> SuggestWorker::take() {
  return result_.take();
}

bool SuggestWorker::wait(std::chrono::milliseconds timeout) {
  return result_.wait(timeout);
}

}  // namespace vdfx::app
