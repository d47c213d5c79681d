// Projection walls (display_surfaces.hpp): the map's templates see the surface the overlapping
// projectors fill, exactly as if it were one wall; a preview window adds nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "confvis/conformal/display_template.hpp"
#include "confvis/engine/display_config.hpp"

using namespace confvis;
using nlohmann::json;

namespace {

json screenWall(const std::string& name, double x0, double x1) {
  return {{"name", name},
          {"lower_left", {x0, 0.6, -2.0}},
          {"lower_right", {x1, 0.6, -2.0}},
          {"upper_left", {x0, 1.95, -2.0}},
          {"resolution", {1920, 1080}}};
}

DisplayConfig screen(json walls) {
  return parseDisplayConfig({{"name", "projectors"},
                             {"reference", {0.0, 1.2, 0.0}},
                             {"source", {{"field", "hemisphere"}}},
                             {"edge_length", 0.5},
                             {"walls", std::move(walls)}},
                            "projectors.json");
}

void expectSameMesh(const TemplateMesh& a, const TemplateMesh& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.lit, b.lit);
  EXPECT_EQ(a.boundary, b.boundary);
  for (std::size_t i = 0; i < a.points.size(); ++i)
    EXPECT_LT(glm::length(a.points[i] - b.points[i]), 1e-12) << i;
}

TEST(ProjectorSurfaceTemplate, OverlappingProjectorsAndAPreviewGiveTheTemplatesOfTheirUnion) {
  json preview = screenWall("preview", -2.2, 2.2);
  preview["preview"] = true;
  const DisplayConfig projectors =
      screen(json::array({screenWall("left", -2.2, 0.2), screenWall("right", -0.2, 2.2),
                          preview}));
  const DisplayConfig single = screen(json::array({screenWall("whole", -2.2, 2.2)}));
  const DisplayTemplates a = buildDisplayTemplates(projectors, 0.5);
  const DisplayTemplates b = buildDisplayTemplates(single, 0.5);
  expectSameMesh(a.target, b.target);
  expectSameMesh(a.source, b.source);
  EXPECT_EQ(a.targetMarkers, b.targetMarkers);
  // Double walls would not give this: the two projectors side by side without overlap (the
  // same outline, split at x = 0) make a template with a seam of extra vertices.
  const DisplayConfig split = screen({screenWall("left", -2.2, 0.0), screenWall("right", 0.0, 2.2)});
  EXPECT_NE(buildDisplayTemplates(split, 0.5).target.points.size(), b.target.points.size());
}

}  // namespace
