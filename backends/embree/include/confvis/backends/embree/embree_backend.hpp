#pragma once
// The Embree ray tracer (backward path of design note §5). Plain mode traces the ordinary
// off-axis rays of every wall; conformal mode redirects them through the retarget map: the
// centre eye exactly, stereo eyes with curved (Exact) or straight (Fast) rays.
#include <memory>
#include <string>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value (options): read it from any number of threads at once.
struct EmbreeOptions {
  // Exact stereo rays: straight segments marched before the curve's straight asymptote.
  int curvedRaySegments = 12;
  int ambientOcclusionSamples = 8;
  // Occlusion radius in metres; 0 = 5 % of the scene's bounding-box diagonal.
  double ambientOcclusionDistance = 0.0;
  int tileSize = 16;
  int threads = 0;  // 0 = all hardware threads (TBB default)
  // The baseline x86-64 (SSE2) shading code even where the CPU has AVX2 (the default picks the
  // AVX2 build there); both render identical pixels. render.json names the one used
  // ("shading_simd").
  bool baselineShading = false;
};

// Thread-safety: as RenderBackend (one thread at a time); each render runs on `threads` TBB
// worker threads of its own.
class EmbreeBackend final : public RenderBackend {
 public:
  explicit EmbreeBackend(const EmbreeOptions& options = {});
  ~EmbreeBackend() override;
  std::string name() const override { return "embree"; }
  void setScene(const Scene& scene) override;
  RenderResult render(const DisplayConfig& config, const RetargetMap* map,
                      const RenderSettings& settings) override;
  // Reuses the pixel storage of result's images, matched by position, where the size agrees.
  // After an error, result holds no images.
  void renderInto(const DisplayConfig& config, const RetargetMap* map,
                  const RenderSettings& settings, RenderResult& result) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace confvis
