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

std::vector<ExtrapolatedSample> extrapolatedErrorSamples(
    const DisplayConfig& config, const DisplayMapEvaluator& test,
    std::span<const DisplayMapEvaluator* const> levels, double order, int samplesPerSide,
    int threads) {
  requireLevels(levels, 2);
  if (!(order > 0))
    throw Error(ErrorCode::InvalidInput, "reference extrapolation order must be > 0, got " +
                                             std::to_string(order));
  const auto rows = sampleLevels(config, test, levels, samplesPerSide, threads);
  const std::size_t last = levels.size() - 1;
  std::vector<ExtrapolatedSample> out;
  for (const auto& row : rows)
    for (const LevelSample& sample : row) {
      const auto& q = sample.shown;
      const Vec3d limit = richardsonExtrapolate(q[last - 1], q[last], order);
      const Vec3d other =
          last >= 2 ? richardsonExtrapolate(q[last - 2], q[last - 1], order) : q[last];
      ExtrapolatedSample& x = out.emplace_back();
      x.wall = sample.wall;
      x.s = sample.s;
      x.t = sample.t;
      x.point = sample.p;
      x.error = norm(limit - sample.p) / sample.pitch;
      x.finestError = norm(q[last] - sample.p) / sample.pitch;
      x.uncertainty = norm(limit - other) / sample.pitch;
      for (std::size_t k = 0; k < last; ++k) x.changes.push_back(norm(q[k + 1] - q[k]) / sample.pitch);
    }
  return out;
}

ExtrapolatedMapError measureMapErrorExtrapolated(
    const DisplayConfig& config, const DisplayMapEvaluator& test,
    std::span<const DisplayMapEvaluator* const> levels, double order, int samplesPerSide,
    int threads) {
  const auto samples = extrapolatedErrorSamples(config, test, levels, order, samplesPerSide, threads);
  std::vector<std::vector<detail::WallSample>> error(1), finest(1);
  std::vector<double> uncertainty;
  for (const ExtrapolatedSample& x : samples) {
    error[0].push_back({x.error, x.wall, x.s, x.t});
    finest[0].push_back({x.finestError, x.wall, x.s, x.t});
    uncertainty.push_back(x.uncertainty);
  }
  ExtrapolatedMapError out;
  out.error = detail::summarizeWallSamples(config, error);
  out.finest = detail::summarizeWallSamples(config, finest);
  detail::fillPercentiles(uncertainty, out.uncertainty);
  return out;
}

}  // namespace confvis
