// Richardson extrapolation of a reference map (map_reference_extrapolation.hpp).
#include "confvis/conformal/map_reference_extrapolation.hpp"

#include <cmath>
#include <string>

#include "confvis/base/error.hpp"
#include "map_accuracy_detail.hpp"
#include "parallel_for.hpp"

namespace confvis {
namespace {

// Per sample point p of a wall: where each level shows the test map's virtual direction at p.
struct LevelSample {
  Vec3d p;
  double pitch;  // metres per pixel of p's wall
  int wall;
  double s, t;
  std::vector<Vec3d> shown;  // one per level
};

std::vector<std::vector<LevelSample>> sampleLevels(
    const DisplayConfig& config, const DisplayMapEvaluator& test,
    std::span<const DisplayMapEvaluator* const> levels, int n, int threads) {
  std::vector<std::vector<LevelSample>> rows(config.walls.size() * n);
  detail::forEachWallGridPoint(config, n, threads, [&](std::size_t row, const Wall& lit,
                                                      const detail::WallGridPoint& at) {
    LevelSample sample{at.p, at.pitch, at.wall, at.s, at.t, {}};
    const auto v = test.toVirtual(sample.p - config.reference);
    if (!v) return;
    for (const DisplayMapEvaluator* level : levels) {
      const auto q = detail::shownAt(config, *level, lit, v->direction);
      if (!q) break;
      sample.shown.push_back(*q);
    }
    if (sample.shown.size() == levels.size()) rows[row].push_back(std::move(sample));
  });
  return rows;
}

void requireLevels(std::span<const DisplayMapEvaluator* const> levels, std::size_t least) {
  if (levels.size() < least)
    throw Error(ErrorCode::InvalidInput, "reference extrapolation needs at least " +
                                             std::to_string(least) + " levels, got " +
                                             std::to_string(levels.size()));
}

}  // namespace

Vec3d richardsonExtrapolate(const Vec3d& coarse, const Vec3d& fine, double order) {
  return fine + (fine - coarse) / (std::exp2(order) - 1);
}

double richardsonOrder(double coarseChange, double fineChange) {
  return std::log2(coarseChange / fineChange);
}

ReferenceConvergence measureReferenceConvergence(
    const DisplayConfig& config, std::span<const DisplayMapEvaluator* const> levels,
    int samplesPerSide, int threads) {
  requireLevels(levels, 2);
  const auto rows = sampleLevels(config, *levels.back(), levels, samplesPerSide, threads);
  ReferenceConvergence out;
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    std::vector<double> pixels;
    for (const auto& row : rows)
      for (const LevelSample& sample : row)
        pixels.push_back(norm(sample.shown[k + 1] - sample.shown[k]) / sample.pitch);
    detail::fillPercentiles(pixels, out.changes.emplace_back());
  }
  if (out.changes.size() >= 2) {
    const ErrorPercentiles& a = out.changes[out.changes.size() - 2];
    const ErrorPercentiles& b = out.changes.back();
    out.orderP50 = richardsonOrder(a.p50, b.p50);
    out.orderP95 = richardsonOrder(a.p95, b.p95);
    out.orderP99 = richardsonOrder(a.p99, b.p99);
  }
  return out;
}

ExtrapolatedMapError measureMapErrorExtrapolated(
    const DisplayConfig& config, const DisplayMapEvaluator& test,
    std::span<const DisplayMapEvaluator* const> levels, double order, int samplesPerSide,
    int threads) {
  requireLevels(levels, 2);
  if (!(order > 0))
    throw Error(ErrorCode::InvalidInput, "reference extrapolation order must be > 0, got " +
                                             std::to_string(order));
  const auto rows = sampleLevels(config, test, levels, samplesPerSide, threads);
  const std::size_t last = levels.size() - 1;
  std::vector<std::vector<detail::WallSample>> error(rows.size()), finest(rows.size());
  std::vector<double> uncertainty;
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (const LevelSample& sample : rows[r]) {
      const auto& q = sample.shown;
      const Vec3d limit = richardsonExtrapolate(q[last - 1], q[last], order);
      error[r].push_back({norm(limit - sample.p) / sample.pitch, sample.wall, sample.s, sample.t});
      finest[r].push_back({norm(q[last] - sample.p) / sample.pitch, sample.wall, sample.s, sample.t});
      const Vec3d other =
          last >= 2 ? richardsonExtrapolate(q[last - 2], q[last - 1], order) : q[last];
      uncertainty.push_back(norm(limit - other) / sample.pitch);
    }
  ExtrapolatedMapError out;
  out.error = detail::summarizeWallSamples(config, error);
  out.finest = detail::summarizeWallSamples(config, finest);
  detail::fillPercentiles(uncertainty, out.uncertainty);
  return out;
}

}  // namespace confvis
