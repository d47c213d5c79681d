// bakeDisplay with confvis's own templates (computeDisplayMap), checked and repaired
// (bake_verdict.hpp). Kept apart from bakeDisplayWith so that programs using only the latter do
// not link the template code.
#include "confvis/conformal/bake_display.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/bake_verdict.hpp"

namespace confvis {
namespace {

struct Attempt {
  double edgeLength;
  bool hemisphere;
  std::string what() const {
    char text[96];
    std::snprintf(text, sizeof text, "edge length %.4g m%s", edgeLength,
                  hemisphere ? ", hemisphere source" : "");
    return text;
  }
};

// The configured bake; for a sphere source then a hemisphere source about the forward direction
// (a display that covers a thin band of directions, like monitors around a desk, cannot show the
// whole sphere without extreme squeezing); then half the edge length (a coarse mesh of small or
// strongly angled walls folds), again with the hemisphere after it. Quarter edges would cost 16
// times the first attempt (20 s for the desktop rig) and fixed nothing the halved ones did not.
std::vector<Attempt> repairPlan(const DisplayConfig& config) {
  const double h = config.edgeLength;
  const bool sphere = config.source == SourceField::FullSphere;
  std::vector<Attempt> plan;
  for (double edge : {h, h / 2}) {
    plan.push_back({edge, false});
    if (sphere) plan.push_back({edge, true});
  }
  return plan;
}

// Where the display is a thin band of directions (monitors side by side around a desk), why no
// repair helps: a conformal map of a disk onto a long thin region crowds most of the disk into
// its middle (the ratio of its ends' scales grows like e^(pi x length / width)), far beyond what
// float cube maps resolve.
std::string bandNote(const DisplayConfig& config) {
  double azMin = 1e9, azMax = -1e9, elMin = 1e9, elMax = -1e9;
  for (const Wall& w : config.walls)
    for (const glm::dvec3& corner : w.corners()) {
      const glm::dvec3 d = corner - config.reference;
      const double az = std::atan2(d.x, -d.z), el = std::atan2(d.y, std::hypot(d.x, d.z));
      azMin = std::min(azMin, az), azMax = std::max(azMax, az);
      elMin = std::min(elMin, el), elMax = std::max(elMax, el);
    }
  const double across = (azMax - azMin) * 180 / std::numbers::pi;
  const double up = (elMax - elMin) * 180 / std::numbers::pi;
  // Thin: one extent over three times the other, and under 45 degrees (a CAVE seen from inside
  // spans 270 degrees around by 71 up and down at its corners, and is no band).
  const bool band = (across > 3 * up && up < 45) || (up > 3 * across && across < 45);
  if (!band) return "";
  char text[320];
  std::snprintf(text, sizeof text,
                "cause: the display is a thin band of directions (%.0f degrees across, %.0f up and "
                "down, seen from the reference point); a conformal map of the virtual field onto "
                "it crowds nearly all of it into the band's middle, beyond what the maps resolve\n",
                across, up);
  return text;
}

// The first map of the repair plan whose bake passes the checks, with that bake (the one
// bakeDisplay returns: the map is baked once).
SourcedDisplayMap computeCheckedDisplayMap(const DisplayConfig& effective,
                                           const BakeDisplayOptions& options) {
  std::vector<std::string> failures;
  std::optional<Error> firstError;
  bool sameErrorEverywhere = true;
  const std::vector<Attempt> plan = repairPlan(effective);
  const auto planStart = SteadyClock::now();
  for (std::size_t k = 0; k < plan.size(); ++k) {
    const double failedSeconds = secondsSince(planStart);  // the attempts before this one
    DisplayConfig config = effective;
    config.edgeLength = plan[k].edgeLength;
    if (plan[k].hemisphere) config.source = SourceField::Hemisphere;
    DisplayMap map;
    try {
      map = computeDisplayMap(config, bakeMapOptions(effective, options));  // route, grading
    } catch (const Error& e) {
      // A flow that fails, a mesh too coarse to map or a repair the display does not allow is one
      // more failed attempt; bad input fails every attempt alike and keeps its own error (below).
      if (e.code() != ErrorCode::Unreachable && e.code() != ErrorCode::InvalidInput) throw;
      if (k == 0) firstError = e;
      else sameErrorEverywhere = sameErrorEverywhere && std::string(e.what()) == firstError->what();
      failures.push_back(plan[k].what() + ": " + e.what());
      continue;
    }
    sameErrorEverywhere = false;
    // The verdict judges the map as bakeDisplayWith bakes it, and that bake is handed back.
    PrebakedRetargetMap baked;
    baked.options = displayBakeOptions(config, options);
    baked.map = bakeRetargetMap(map, config.cubeResolution, baked.options, &baked.timings);
    const auto judging = SteadyClock::now();
    const BakeVerdict verdict = judgeBake(map, baked.map);
    if (verdict.ok()) {
      map.stats["checks"] = verdict.toJson();
      map.stats["checks"]["seconds"] = secondsSince(judging);
      if (k > 0)
        map.stats["repair"] = {{"applied", plan[k].what()},
                               {"failed_attempts", failures},
                               {"failed_attempts_seconds", failedSeconds}};
      SourcedDisplayMap result(std::move(map));
      result.baked = std::move(baked);
      return result;
    }
    failures.push_back(plan[k].what() + ": " + verdict.summary());
  }
  if (firstError && sameErrorEverywhere && firstError->code() == ErrorCode::InvalidInput)
    throw *firstError;
  std::string tried;
  for (const std::string& f : failures) tried += "\n  " + f;
  throw Error(ErrorCode::Unreachable,
              effective.name + ": no usable conformal map (a broken one is never returned); "
                               "tried:" + tried + "\n" + bandNote(effective) +
                  "fix: check the walls and the reference point (every wall must face it), "
                  "give a hemisphere source (\"source\": {\"field\": \"hemisphere\", \"axis\": "
                  "[x, y, z]} pointing into the display) or a smaller \"edge_length\", or render "
                  "without the map (render --mode plain)");
}

}  // namespace

BakedDisplay bakeDisplay(const DisplayConfig& config, const BakeDisplayOptions& options) {
  return bakeDisplayWith(config, options, [&](const DisplayConfig& effective) {
    return computeCheckedDisplayMap(effective, options);
  });
}

}  // namespace confvis
