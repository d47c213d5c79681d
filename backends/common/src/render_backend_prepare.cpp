#include "confvis/backends/render_backend.hpp"

namespace confvis {

void RenderBackend::prepare(const DisplayConfig& config, const RenderSettings& settings) {
  // Every stage of a frame runs once (pipelines, per-wall targets, the conformal pre-pass), with
  // a map that needs no bake: the warp's cost does not depend on what the map holds.
  const RetargetMap identity = RetargetMap::identity(16, config.reference);
  RenderResult discarded;
  renderInto(config, settings.mode == RenderMode::Conformal ? &identity : nullptr, settings,
             discarded);
}

}  // namespace confvis
