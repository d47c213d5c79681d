// Whether a baked map is fit to use (bake_verdict.hpp).
#include "confvis/conformal/bake_verdict.hpp"

#include <algorithm>
#include <cstdio>

#include "confvis/conformal/baked_map_quality.hpp"

namespace confvis {
namespace {

// Triangles whose disk orientation differs from the disk's own (the sign of the total signed
// area: the boundary runs counter-clockwise), or that collapsed.
std::size_t flippedDiskTriangles(const SphereDiskMesh& mesh) {
  std::vector<double> areas;
  areas.reserve(mesh.triangles.size());
  double total = 0;
  for (const auto& t : mesh.triangles) {
    const auto a = mesh.disk[t[0]], b = mesh.disk[t[1]], c = mesh.disk[t[2]];
    areas.push_back(std::imag(std::conj(b - a) * (c - a)));
    total += areas.back();
  }
  return static_cast<std::size_t>(
      std::count_if(areas.begin(), areas.end(), [&](double area) { return !(area * total > 0); }));
}

std::string format(const char* pattern, double value) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

std::string BakeVerdict::summary() const {
  if (problems.empty()) return "no problems";
  std::string text;
  for (const std::string& p : problems) text += (text.empty() ? "" : "; ") + p;
  return text;
}

nlohmann::json BakeVerdict::toJson() const {
  return {{"flipped_triangles", flippedTriangles},
          {"flipped_texels", flippedTexels},
          {"coverage", coverage},
          {"ray_ratio_p99", ratioP99},
          {"problems", problems}};
}

BakeVerdict judgeBake(const DisplayMap& displayMap, const RetargetMap& map) {
  BakeVerdict verdict;
  verdict.flippedTriangles =
      flippedDiskTriangles(displayMap.source) + flippedDiskTriangles(displayMap.target);
  const int stride = std::max(1, map.resolution() / 128);
  const BakedConformality ray = measureBakedConformality(
      map.ray, {.margin = 2, .discontinuityTolerance = 0.5, .stride = stride});
  verdict.flippedTexels = ray.flipped;
  verdict.ratioP99 = ray.ratioP99;
  const CoverageStats coverage = measureCoverage(map, 1.0, stride);
  verdict.coverage = coverage.sourceTexels > 0
                         ? static_cast<double>(coverage.covered + coverage.unlit) /
                               static_cast<double>(coverage.sourceTexels)
                         : 0.0;
  if (verdict.flippedTriangles > 0)
    verdict.problems.push_back(std::to_string(verdict.flippedTriangles) +
                               " triangles flipped in the disk maps");
  if (verdict.flippedTexels > 0)
    verdict.problems.push_back(std::to_string(verdict.flippedTexels) +
                               " texels of the map reverse orientation");
  if (verdict.coverage < kMinCoverage)
    verdict.problems.push_back(
        format("the display shows only %.1f %% of the source field", 100 * verdict.coverage));
  if (verdict.ratioP99 > kMaxRatioP99)
    verdict.problems.push_back(
        format("conformality outliers (singular-value ratio p99 %.1f, a conformal map has 1)",
               verdict.ratioP99));
  return verdict;
}

std::string repairNote(const nlohmann::json& sidecar) {
  const nlohmann::json* stats = nullptr;
  if (sidecar.contains("timings") && sidecar["timings"].contains("display_map"))
    stats = &sidecar["timings"]["display_map"];
  if (!stats || !stats->contains("repair")) return "";
  const nlohmann::json& repair = (*stats)["repair"];
  std::string note = "repaired with " + repair.value("applied", std::string("?"));
  if (repair.contains("failed_attempts") && !repair["failed_attempts"].empty())
    note += " after " + repair["failed_attempts"].front().get<std::string>();
  return note;
}

}  // namespace confvis
