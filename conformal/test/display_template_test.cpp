// Display templates: topology, the cut trees of the dissertation (8.3.2), bezels, stitching and
// the refinement bound, checked against the geometry of each display.
#include "confvis/conformal/display_template.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "confvis/base/error.hpp"
#include "display_test_configs.hpp"

using namespace confvis;
using namespace confvis::testing;

namespace {

constexpr double kEps = 1e-9;

bool same(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < kEps; }

// V - E + F and the number of boundary edges, counted from the triangle list alone.
struct Counts {
  int euler = 0, boundaryEdges = 0, nonManifoldEdges = 0;
};
Counts count(const TemplateMesh& mesh) {
  std::map<std::pair<int, int>, int> edges;
  std::set<int> vertices;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      vertices.insert(t[k]);
      ++edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    }
  Counts c;
  c.euler = static_cast<int>(vertices.size()) - static_cast<int>(edges.size()) +
            static_cast<int>(mesh.triangles.size());
  for (const auto& [e, n] : edges) {
    c.boundaryEdges += n == 1;
    c.nonManifoldEdges += n > 2;
  }
  return c;
}

void expectDisk(const TemplateMesh& mesh, const std::string& what) {
  const Counts c = count(mesh);
  EXPECT_EQ(c.euler, 1) << what;
  EXPECT_EQ(c.nonManifoldEdges, 0) << what;
  EXPECT_EQ(c.boundaryEdges, static_cast<int>(mesh.boundary.size()))
      << what << ": one boundary loop";
}

// Every triangle faces the reference point counter-clockwise.
void expectFacingReference(const TemplateMesh& mesh, const glm::dvec3& c, const std::string& what) {
  int wrong = 0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 n =
        glm::cross(mesh.points[t[1]] - mesh.points[t[0]], mesh.points[t[2]] - mesh.points[t[0]]);
    if (glm::dot(n, c - mesh.points[t[0]]) <= 0) ++wrong;
  }
  EXPECT_EQ(wrong, 0) << what;
}

int countOnBoundary(const TemplateMesh& mesh, const glm::dvec3& p) {
  return static_cast<int>(std::count_if(mesh.boundary.begin(), mesh.boundary.end(),
                                        [&](int v) { return same(mesh.points[v], p); }));
}

bool onSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const double t = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
  return t >= -kEps && t <= 1 + kEps && glm::length(a + t * (b - a) - p) < 1e-7;
}

const std::vector<glm::dvec3> kCeilingCorners{
    {-1.5, 1.5, -1.5}, {1.5, 1.5, -1.5}, {1.5, 1.5, 1.5}, {-1.5, 1.5, 1.5}};

// Source boundary of a star cut: the centre once per arm, every leaf once, every other vertex on
// one of the arms (each arm twice, once per side).
void expectStar(const TemplateMesh& source, const glm::dvec3& centre,
                const std::vector<glm::dvec3>& leaves) {
  EXPECT_EQ(countOnBoundary(source, centre), static_cast<int>(leaves.size()));
  for (const glm::dvec3& leaf : leaves) EXPECT_EQ(countOnBoundary(source, leaf), 1);
  for (int v : source.boundary) {
    bool onArm = false;
    for (const glm::dvec3& leaf : leaves)
      onArm = onArm || onSegment(source.points[v], centre, leaf);
    EXPECT_TRUE(onArm) << source.points[v].x << " " << source.points[v].y << " "
                       << source.points[v].z;
  }
}

void expectMarkersCorrespond(const DisplayTemplates& t) {
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 s = t.source.points[t.sourceMarkers[k]],
                     d = t.target.points[t.targetMarkers[k]];
    EXPECT_TRUE(same(s, d)) << "marker " << k;
    EXPECT_EQ(countOnBoundary(t.source, s), 1);
    EXPECT_EQ(countOnBoundary(t.target, d), 1);
  }
}

double area(const TemplateMesh& m, int t) {
  const auto& v = m.triangles[t];
  return 0.5 *
         glm::length(glm::cross(m.points[v[1]] - m.points[v[0]], m.points[v[2]] - m.points[v[0]]));
}

double totalArea(const TemplateMesh& m) {
  double a = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) a += area(m, static_cast<int>(t));
  return a;
}

}  // namespace

TEST(DisplayTemplate, Cave5IsCutAlongTheStarFromTheCeilingCentreToItsCorners) {
  const DisplayConfig config = shipped("cave5");
  const DisplayTemplates t = buildDisplayTemplates(config, 0.5);
  EXPECT_EQ(t.sourceKind, SourceKind::Box);
  expectDisk(t.source, "source");
  expectDisk(t.target, "target");
  expectFacingReference(t.source, config.reference, "source");
  expectFacingReference(t.target, config.reference, "target");
  // Target boundary: exactly the walls' top edges, through the four top corners.
  for (int v : t.target.boundary) EXPECT_NEAR(t.target.points[v].y, 1.5, kEps);
  for (const glm::dvec3& corner : kCeilingCorners) EXPECT_EQ(countOnBoundary(t.target, corner), 1);
  expectStar(t.source, {0, 1.5, 0}, kCeilingCorners);
  expectMarkersCorrespond(t);
  // Source = the closed cube: 6 faces of 9 m², the target its 5 walls.
  EXPECT_NEAR(totalArea(t.source), 54, 1e-9);
  EXPECT_NEAR(totalArea(t.target), 45, 1e-9);
  for (std::uint8_t lit : t.target.lit) EXPECT_EQ(lit, 1);
}

TEST(DisplayTemplate, Cave6SourceAndTargetAreTheSameMeshCutAlongTheCeilingStar) {
  const DisplayTemplates t = buildDisplayTemplates(shipped("cave6"), 0.5);
  EXPECT_EQ(t.sourceKind, SourceKind::Closed);
  expectDisk(t.target, "target");
  EXPECT_EQ(t.source.points, t.target.points);
  EXPECT_EQ(t.source.triangles, t.target.triangles);
  EXPECT_EQ(t.sourceMarkers, t.targetMarkers);
  expectStar(t.target, {0, 1.5, 0}, kCeilingCorners);
  EXPECT_NEAR(totalArea(t.target), 54, 1e-9);
}

TEST(DisplayTemplate, Cave4JoinsTheCeilingAndBackStarsThroughTheirSharedEdge) {
  const DisplayTemplates t = buildDisplayTemplates(shipped("cave4"), 0.5);
  EXPECT_EQ(t.sourceKind, SourceKind::Box);
  expectDisk(t.source, "source");
  expectDisk(t.target, "target");
  expectMarkersCorrespond(t);
  // Leaves: the corners where only one missing face meets two walls.
  const std::vector<glm::dvec3> leaves{
      {-1.5, 1.5, -1.5}, {1.5, 1.5, -1.5}, {-1.5, -1.5, 1.5}, {1.5, -1.5, 1.5}};
  ASSERT_EQ(t.cutLeaves.size(), leaves.size());
  for (const glm::dvec3& leaf : leaves) {
    EXPECT_EQ(std::count_if(t.cutLeaves.begin(), t.cutLeaves.end(),
                            [&](auto& p) { return same(p, leaf); }),
              1);
    EXPECT_EQ(countOnBoundary(t.source, leaf), 1);
  }
  // Nodes: the ceiling's and back wall's centres (two arms and the joint each) and the joint.
  EXPECT_EQ(countOnBoundary(t.source, {0, 1.5, 0}), 3);
  EXPECT_EQ(countOnBoundary(t.source, {0, 0, 1.5}), 3);
  EXPECT_EQ(countOnBoundary(t.source, {0, 1.5, 1.5}), 2);
  // The top-back corners are not on the cut: the uncovered region is concave there.
  EXPECT_EQ(countOnBoundary(t.source, {-1.5, 1.5, 1.5}), 0);
  EXPECT_NEAR(totalArea(t.target), 36, 1e-9);
}

TEST(DisplayTemplate, Cave3CutRunsThroughCeilingBackAndFloorToTheFrontCorners) {
  const DisplayTemplates t = buildDisplayTemplates(shipped("cave3"), 0.5);
  expectDisk(t.source, "source");
  expectDisk(t.target, "target");
  expectMarkersCorrespond(t);
  for (const glm::dvec3& leaf : std::vector<glm::dvec3>{
           {-1.5, 1.5, -1.5}, {1.5, 1.5, -1.5}, {-1.5, -1.5, -1.5}, {1.5, -1.5, -1.5}})
    EXPECT_EQ(countOnBoundary(t.source, leaf), 1);
  EXPECT_EQ(t.cutLeaves.size(), 4u);
  // Ceiling and floor centres: two arms and a joint; the back centre: two joints.
  EXPECT_EQ(countOnBoundary(t.source, {0, 1.5, 0}), 3);
  EXPECT_EQ(countOnBoundary(t.source, {0, -1.5, 0}), 3);
  EXPECT_EQ(countOnBoundary(t.source, {0, 0, 1.5}), 2);
}

TEST(DisplayTemplate, MovingTheReferenceMovesTheStarCentreToItsProjectionOnTheMissingFace) {
  DisplayConfig config = shipped("cave5");
  config.reference = {0.4, -0.3, 0.2};
  const DisplayTemplates t = buildDisplayTemplates(config, 0.5);
  expectDisk(t.source, "source");
  expectFacingReference(t.source, config.reference, "source");
  expectStar(t.source, {0.4, 1.5, 0.2}, kCeilingCorners);
  EXPECT_EQ(countOnBoundary(t.source, {0, 1.5, 0}), 0);
  expectMarkersCorrespond(t);
  // The walls' fans start at the reference's feet too (the "green spheres").
  for (const glm::dvec3& foot :
       std::vector<glm::dvec3>{{0.4, -0.3, -1.5}, {-1.5, -0.3, 0.2}, {0.4, -1.5, 0.2}})
    EXPECT_TRUE(std::any_of(t.target.points.begin(), t.target.points.end(),
                            [&](auto& p) { return same(p, foot); }));
}

TEST(DisplayTemplate, RefinementSplitsEveryEdgeBelowTheThresholdAndNoFurther) {
  for (const char* name : {"cave5", "cave3", "md230x6", "flat-wall"})
    for (double scale : {1.0, 0.45}) {
      const DisplayConfig config = shipped(name);
      const double limit = scale * config.edgeLength * 2;
      const DisplayTemplates t = buildDisplayTemplates(config, limit);
      // Bezel corners are smaller than any threshold here, so they are never split.
      const bool bezels = std::string(name) == "md230x6";
      for (const TemplateMesh* m : {&t.source, &t.target}) {
        double maxEdge = 0, minLongest = 1e9;
        for (const auto& tri : m->triangles) {
          double longest = 0;
          for (int k = 0; k < 3; ++k)
            longest =
                std::max(longest, glm::length(m->points[tri[k]] - m->points[tri[(k + 1) % 3]]));
          maxEdge = std::max(maxEdge, longest);
          minLongest = std::min(minLongest, longest);
        }
        EXPECT_LE(maxEdge, limit) << name;
        if (!bezels) {
          EXPECT_GT(minLongest, limit / 2)
              << name << ": a triangle was split although its edges were short";
        }
      }
    }
}

TEST(DisplayTemplate, BezelsAreCoveredButUnlitAndNoTriangleStraddlesTheirBorder) {
  const DisplayConfig config = shipped("md230x6");
  const DisplayTemplates t = buildDisplayTemplates(config);
  EXPECT_EQ(t.sourceKind, SourceKind::Hemisphere);
  expectDisk(t.target, "target");
  expectFacingReference(t.target, config.reference, "target");
  ASSERT_EQ(t.target.lit.size(), t.target.triangles.size());
  double litArea = 0, unlitArea = 0, litExpected = 0, wallArea = 0;
  for (const Wall& w : config.walls) {
    litExpected += w.litRectangle().widthMetres() * w.litRectangle().heightMetres();
    wallArea += w.widthMetres() * w.heightMetres();
  }
  for (std::size_t i = 0; i < t.target.triangles.size(); ++i) {
    const auto& tri = t.target.triangles[i];
    // Every corner of a lit triangle lies in the lit rectangle of one wall; every unlit one has
    // its centroid outside all lit rectangles.
    auto inLitArea = [&](const glm::dvec3& p) {
      for (const Wall& w : config.walls) {
        const Wall lit = w.litRectangle();
        const glm::dvec3 d = p - lit.lowerLeft;
        if (std::abs(glm::dot(d, lit.normal())) < kEps && glm::dot(d, lit.right()) > -kEps &&
            glm::dot(d, lit.right()) < lit.widthMetres() + kEps && glm::dot(d, lit.up()) > -kEps &&
            glm::dot(d, lit.up()) < lit.heightMetres() + kEps)
          return true;
      }
      return false;
    };
    const glm::dvec3 centroid =
        (t.target.points[tri[0]] + t.target.points[tri[1]] + t.target.points[tri[2]]) / 3.0;
    if (t.target.lit[i]) {
      for (int v : tri) EXPECT_TRUE(inLitArea(t.target.points[v]));
      litArea += area(t.target, static_cast<int>(i));
    } else {
      EXPECT_FALSE(inLitArea(centroid));
      unlitArea += area(t.target, static_cast<int>(i));
    }
  }
  EXPECT_NEAR(litArea, litExpected, 1e-9);
  EXPECT_NEAR(unlitArea, wallArea - litExpected, 1e-9);
  EXPECT_GT(unlitArea, 0.01);
  // The hemisphere's rim lies in the plane through the reference perpendicular to the axis.
  for (int v : t.source.boundary) EXPECT_NEAR(t.source.points[v].z, 0, kEps);
}

TEST(DisplayTemplate, FlatWallMarkersAreThreeCornersAndTheRimPointsAtTheirAzimuths) {
  const DisplayConfig config = shipped("flat-wall");
  const DisplayTemplates t = buildDisplayTemplates(config);
  expectDisk(t.source, "source");
  expectDisk(t.target, "target");
  const Wall& w = config.walls.front();
  const std::vector<glm::dvec3> corners{w.lowerLeft, w.lowerRight, w.upperRight(), w.upperLeft};
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 corner = t.target.points[t.targetMarkers[k]];
    EXPECT_TRUE(
        std::any_of(corners.begin(), corners.end(), [&](auto& p) { return same(p, corner); }));
    const glm::dvec3 rim = t.source.points[t.sourceMarkers[k]];
    EXPECT_NEAR(rim.z, 0, kEps);
    EXPECT_NEAR(std::atan2(rim.y, rim.x), std::atan2(corner.y, corner.x), 1e-12);
  }
}

TEST(DisplayTemplate, TiledWallWithTJunctionsIsStitchedIntoOneDisk) {
  // Three panels below, two wider ones above: the lower seams end inside the upper panels' edges.
  const Bezel b{0.01, 0.01, 0.01, 0.01};
  const DisplayConfig config =
      makeDisplay("t-junctions",
                  {makeWall("a", {-1.5, -1, -1}, {-0.5, -1, -1}, {-1.5, 0, -1}, b),
                   makeWall("b", {-0.5, -1, -1}, {0.5, -1, -1}, {-0.5, 0, -1}, b),
                   makeWall("c", {0.5, -1, -1}, {1.5, -1, -1}, {0.5, 0, -1}, b),
                   makeWall("d", {-1.5, 0, -1}, {0, 0, -1}, {-1.5, 1, -1}, b),
                   makeWall("e", {0, 0, -1}, {1.5, 0, -1}, {0, 1, -1}, b)},
                  SourceField::Hemisphere);
  const DisplayTemplates t = buildDisplayTemplates(config, 0.3);
  expectDisk(t.target, "target");
  EXPECT_NEAR(totalArea(t.target), 6, 1e-9);
  // The boundary is the outer rectangle only: every boundary vertex lies on it.
  for (int v : t.target.boundary) {
    const glm::dvec3& p = t.target.points[v];
    EXPECT_TRUE(std::abs(std::abs(p.x) - 1.5) < kEps || std::abs(std::abs(p.y) - 1) < kEps);
  }
}

TEST(DisplayTemplate, OnlyABezelFreeClosedDisplayHasTheIdentityMap) {
  EXPECT_TRUE(displayMapIsIdentity(shipped("cave6")));
  DisplayConfig offCentre = shipped("cave6");
  offCentre.reference = {0.4, -0.3, 0.7};  // still enclosed: source and target stay the same mesh
  EXPECT_TRUE(displayMapIsIdentity(offCentre));
  // Bezels are unlit: the map is the identity, but its alpha must mark them, so it is baked.
  DisplayConfig bezels = shipped("cave6");
  bezels.walls[0].bezel = {0.02, 0.02, 0.02, 0.02};
  EXPECT_FALSE(displayMapIsIdentity(bezels));
  DisplayConfig hemisphere = shipped("cave6");
  hemisphere.source = SourceField::Hemisphere;
  EXPECT_FALSE(displayMapIsIdentity(hemisphere));
  for (const char* open : {"cave5", "cave4", "cave3", "flat-wall", "md230x6"})
    EXPECT_FALSE(displayMapIsIdentity(shipped(open))) << open;
  // A malformed display is reported, not taken for "not the identity".
  DisplayConfig broken = shipped("cave6");
  broken.walls.pop_back();
  broken.walls.push_back(makeWall("tilted", {-1.5, 1.5, 1.5}, {1.5, 1.5, 1.5}, {-1.5, 1.0, -1.5}));
  EXPECT_THROW(displayMapIsIdentity(broken), Error);
}
