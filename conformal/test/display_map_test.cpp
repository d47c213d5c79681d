// computeDisplayMap against closed forms: the 6-sided CAVE maps to itself, a hemisphere maps by
// stereographic projection, a display covering exactly the front hemisphere gives the identity,
// and the mirror-symmetric 5-sided CAVE gets mirror-symmetric disks centred on the forward
// direction.
#include "confvis/conformal/display_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <tuple>

#include "confvis/base/error.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/distortion.hpp"
#include "../src/display_alignment.hpp"
#include "display_test_configs.hpp"

using namespace confvis;
using namespace confvis::testing;
using Complex = std::complex<double>;

namespace {

conformal::TriMesh sphereMesh(const SphereDiskMesh& m) {
  conformal::TriMesh mesh;
  for (const Vec3d& p : m.sphere) mesh.add_vertex({p.x, p.y, p.z});
  for (const auto& t : m.triangles)
    mesh.add_face(conformal::TriMesh::VertexHandle(t[0]), conformal::TriMesh::VertexHandle(t[1]),
                  conformal::TriMesh::VertexHandle(t[2]));
  return mesh;
}

// The disk point of a sphere direction (the mesh's piecewise-linear map).
Complex diskAt(const SphereDiskMesh& m, const Vec3d& direction) {
  const detail::SphereLocation at = detail::locateDirection(m, normalized(direction));
  EXPECT_GE(at.triangle, 0) << "direction not in the mesh";
  return at.triangle >= 0 ? detail::diskPoint(m, at) : Complex(2, 2);
}

// A valid aligned disk map: the anchor (forward) direction at 0 with up along +i, boundary on the
// unit circle in counter-clockwise order, no triangle flipped, close to conformal.
void expectAlignedDiskMap(const SphereDiskMesh& m, const std::string& what,
                          const Vec3d& anchor = {0, 0, -1}) {
  ASSERT_EQ(m.disk.size(), m.sphere.size()) << what;
  EXPECT_LT(std::abs(diskAt(m, anchor)), 1e-12) << what;
  // Up: a step of a degree above the anchor lands on the positive imaginary axis, to the PL
  // map's own turn between neighbouring triangles.
  const Vec3d up = detail::upAt(normalized(anchor));
  const Complex above = diskAt(m, std::cos(0.02) * normalized(anchor) + std::sin(0.02) * up);
  EXPECT_NEAR(std::arg(above), M_PI / 2, 0.05) << what;
  double winding = 0;
  for (std::size_t i = 0; i < m.boundary.size(); ++i) {
    const Complex z = m.disk[m.boundary[i]];
    EXPECT_NEAR(std::abs(z), 1, 1e-8) << what;
    winding += std::arg(m.disk[m.boundary[(i + 1) % m.boundary.size()]] / z);
  }
  EXPECT_NEAR(winding, 2 * M_PI, 1e-6) << what << ": boundary runs counter-clockwise once";
  const auto stats = conformal::measureDistortion(sphereMesh(m), m.disk);
  EXPECT_EQ(stats.flippedFaces, 0) << what;
  // Coarse test meshes: the median singular-value ratio is ~1.2 at 0.4 m and halves its excess
  // with each halving of the edge length (measured).
  EXPECT_LT(stats.ratioP50, 1.25) << what;
}

int vertexToward(const SphereDiskMesh& m, const Vec3d& direction) {
  const Vec3d d = normalized(direction);
  int best = 0;
  for (std::size_t v = 0; v < m.sphere.size(); ++v)
    if (dot(m.sphere[v], d) > dot(m.sphere[best], d)) best = static_cast<int>(v);
  return best;
}

// Stereographic projection of the hemisphere about `axis` (from -axis): the axis goes to 0 and
// `up` = right x axis along +i, as the alignment puts them.
std::vector<Complex> alignedStereographic(const SphereDiskMesh& m, const Vec3d& axis,
                                          const Vec3d& right) {
  const Vec3d up = cross(right, axis);  // seen from the reference: right, up, axis forward
  std::vector<Complex> z;
  for (const Vec3d& p : m.sphere)
    z.emplace_back(dot(p, right) / (1 + dot(p, axis)), dot(p, up) / (1 + dot(p, axis)));
  return z;
}

double maxDistance(const std::vector<Complex>& a, const std::vector<Complex>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

// T_ray at every target vertex: its disk point located in the source disk, the source sphere
// interpolated there; returns the largest angle to the target vertex's own direction.
double maxIdentityError(const DisplayMap& map) {
  double worst = 0;
  for (std::size_t v = 0; v < map.target.sphere.size(); ++v) {
    const Complex z = map.target.disk[v];
    double bestOutside = 1e9;
    Vec3d image{0.0};
    for (const auto& t : map.source.triangles) {
      const Complex a = map.source.disk[t[0]], b = map.source.disk[t[1]], c = map.source.disk[t[2]];
      const double area = std::imag(std::conj(b - a) * (c - a));
      const double l1 = std::imag(std::conj(c - b) * (z - b)) / area,
                   l2 = std::imag(std::conj(a - c) * (z - c)) / area;
      const double l0 = 1 - l1 - l2;
      const double outside = std::max({0.0, -l0, -l1, -l2});
      if (outside < bestOutside) {
        bestOutside = outside;
        image = normalized(l1 * map.source.sphere[t[0]] + l2 * map.source.sphere[t[1]] +
                           l0 * map.source.sphere[t[2]]);
      }
    }
    worst = std::max(worst, angleBetween(image, map.target.sphere[v]));
  }
  return worst;
}

}  // namespace

TEST(DisplayMap, SixSidedCaveIsTheIdentity) {
  DisplayMapOptions options;
  options.edgeLength = 0.5;
  const DisplayMap map = computeDisplayMap(shipped("cave6"), options);
  expectAlignedDiskMap(map.target, "target");
  EXPECT_EQ(map.source.sphere, map.target.sphere);
  EXPECT_EQ(map.source.triangles, map.target.triangles);
  EXPECT_EQ(map.source.disk, map.target.disk);
  EXPECT_EQ(map.sourceMarkers, map.targetMarkers);
  EXPECT_LT(maxIdentityError(map), 1e-9);
}

TEST(DisplayMap, FiveSidedCaveDisksAreCentredOnForwardAndMirrorSymmetric) {
  DisplayMapOptions options;
  options.edgeLength = 0.3;
  const DisplayMap map = computeDisplayMap(shipped("cave5"), options);
  expectAlignedDiskMap(map.source, "source");
  expectAlignedDiskMap(map.target, "target");
  // The display is symmetric under the left/right mirror x -> -x, which keeps forward and up:
  // in both disks it becomes z -> -conj(z). The floor centre lies on the imaginary axis (below
  // the centre), mirror-image ceiling corners at mirror-image points.
  for (const SphereDiskMesh* m : {&map.source, &map.target}) {
    const Complex floor = m->disk[vertexToward(*m, {0, -1, 0})];
    EXPECT_LT(std::abs(floor.real()), 1e-6);
    EXPECT_LT(floor.imag(), -0.1);
    for (double z : {-1.0, 1.0}) {
      const Complex left = m->disk[vertexToward(*m, {-1, 1, z})];
      const Complex right = m->disk[vertexToward(*m, {1, 1, z})];
      EXPECT_LT(std::abs(left + std::conj(right)), 1e-6) << "ceiling corners at z = " << z;
    }
  }
  for (const char* stage : {"template", "flow", "alignment"})
    EXPECT_GE(map.stats.at(stage).get<double>(), 0);
  EXPECT_EQ(map.stats["anchor"]["rule"], "straight ahead");
  EXPECT_EQ(map.stats["source"]["vertices"].get<std::size_t>(), map.source.sphere.size());
  EXPECT_EQ(map.stats["target"]["triangles"].get<std::size_t>(), map.target.triangles.size());
}

TEST(DisplayMap, HemisphereSourceIsTheStereographicProjectionUpToMobius) {
  const DisplayConfig config = shipped("flat-wall");
  double previous = 1e9;
  for (double h : {0.4, 0.2}) {
    DisplayMapOptions options;
    options.edgeLength = h;
    const DisplayMap map = computeDisplayMap(config, options);
    expectAlignedDiskMap(map.source, "source");
    expectAlignedDiskMap(map.target, "target");
    const double error =
        maxDistance(map.source.disk,
                    alignedStereographic(map.source, {0, 0, -1}, {1, 0, 0}));
    EXPECT_LT(error, previous * 0.7) << "h = " << h;
    previous = error;
  }
  EXPECT_LT(previous, 0.02);
}

TEST(DisplayMap, DisplayCoveringExactlyTheFrontHemisphereIsTheIdentity) {
  // The display covers the hemisphere the source shows, with a different mesh: T_ray is the
  // identity up to discretisation, and both maps are the stereographic projection.
  const DisplayConfig config = frontHemisphereDisplay();
  DisplayMapOptions options;
  options.edgeLength = 0.2;
  const DisplayMap map = computeDisplayMap(config, options);
  expectAlignedDiskMap(map.target, "target");
  EXPECT_LT(maxDistance(map.target.disk,
                        alignedStereographic(map.target, {0, 0, -1}, {1, 0, 0})),
            0.02);
  EXPECT_LT(maxDistance(map.source.disk,
                        alignedStereographic(map.source, {0, 0, -1}, {1, 0, 0})),
            0.02);
  EXPECT_LT(maxIdentityError(map), 0.025);  // measured 0.015 rad at 0.2 m
  EXPECT_NE(map.source.sphere.size(), map.target.sphere.size())
      << "the test needs two different meshes";
}

TEST(DisplayMap, MovedReferenceOtherCavesAndTheMonitorWallGiveValidMaps) {
  DisplayConfig moved = shipped("cave5");
  moved.reference = {0.5, -0.4, 0.3};
  for (const DisplayConfig& config :
       {moved, shipped("cave4"), shipped("cave3"), shipped("md230x6")}) {
    DisplayMapOptions options;
    options.edgeLength = config.name == "md230x6" ? 0.1 : 0.4;
    const DisplayMap map = computeDisplayMap(config, options);
    expectAlignedDiskMap(map.source, config.name + " source");
    expectAlignedDiskMap(map.target, config.name + " target");
    // Sphere sources share the markers' directions (cut leaves); hemisphere markers share only
    // their azimuths about the axis.
    for (int k = 0; k < 3 && config.source == SourceField::FullSphere; ++k) {
      EXPECT_LT(angleBetween(map.source.sphere[map.sourceMarkers[k]],
                             map.target.sphere[map.targetMarkers[k]]),
                1e-12)
          << config.name;
    }
    ASSERT_EQ(map.target.lit.size(), map.target.triangles.size());
    EXPECT_EQ(std::count(map.target.lit.begin(), map.target.lit.end(), 0) > 0,
              config.name == "md230x6");
  }
}

TEST(DisplayMap, SixSidedCaveWithBezelsIsTheIdentityWithUnlitFrames) {
  // With bezels the ceiling is a grid, so the closed display is cut along a cross of grid lines.
  DisplayConfig config = shipped("cave6");
  for (Wall& w : config.walls) w.bezel = {0.05, 0.05, 0.05, 0.05};
  DisplayMapOptions options;
  options.edgeLength = 0.6;
  const DisplayMap map = computeDisplayMap(config, options);
  expectAlignedDiskMap(map.target, "target");
  EXPECT_EQ(map.source.disk, map.target.disk);
  EXPECT_LT(maxIdentityError(map), 1e-9);
  // The ceiling's cross: its centre (a grid vertex on the ceiling) opens into four boundary
  // copies, its four leaves on the lit area's sides appear once.
  std::map<std::tuple<double, double, double>, int> copies;
  for (int v : map.target.boundary) {
    const Vec3d& d = map.target.sphere[v];
    ++copies[{d.x, d.y, d.z}];
  }
  int centres = 0;
  for (const auto& [d, count] : copies) {
    EXPECT_TRUE(count == 1 || count == 2 || count == 4);
    if (count == 4) {
      ++centres;
      EXPECT_GT(std::get<1>(d), 0.5) << "on the ceiling";
    }
  }
  EXPECT_EQ(centres, 1);
  EXPECT_GT(std::count(map.target.lit.begin(), map.target.lit.end(), 0), 0);
}
