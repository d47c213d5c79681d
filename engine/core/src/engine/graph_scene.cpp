// graph (dissertation Fig. 8.9): a dense clustered node-link graph all around the viewer, the
// kind of data whose local shapes the conformal map must keep readable. Deterministic: a fixed
// seed and our own random-number conversions (std:: distributions differ between libraries).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include "builtin_scene_parts.hpp"
#include "confvis/base/error.hpp"

namespace confvis {

namespace {

constexpr std::uint64_t kGraphSeed = 0x5eed'c0f1'9a11'0001ULL;
constexpr float kNodeRadius = 0.08f;
constexpr float kEdgeRadius = 0.012f;
constexpr double kClusterSpread = 0.9;  // standard deviation of node offsets, metres
constexpr double kMinDistance = 3.0, kMaxDistance = 15.0;
constexpr int kNeighboursPerNode = 3;            // intra-cluster edges to nearest nodes
constexpr int kLinkedClusters = 2;               // each cluster links to its nearest clusters
constexpr int kEdgesPerClusterLink = 3;

// splitmix64: tiny, fast, and identical on every platform.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double normal() {  // Box-Muller
    const double u1 = 1.0 - uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  glm::dvec3 direction() {  // uniform on the unit sphere
    const double z = 2.0 * uniform() - 1.0;
    const double phi = 2.0 * std::numbers::pi * uniform();
    const double r = std::sqrt(1.0 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  std::size_t index(std::size_t n) { return static_cast<std::size_t>(next() % n); }

 private:
  std::uint64_t state_;
};

// Unit icosphere: icosahedron with each triangle split into four `subdivisions` times.
Mesh unitIcosphere(int subdivisions) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  Mesh mesh;
  mesh.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (glm::vec3& p : mesh.positions) p = glm::normalize(p);
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<unsigned, unsigned>, unsigned> midpoints;
    const auto midpoint = [&](unsigned a, unsigned b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoints.try_emplace(key, 0u);
      if (inserted) {
        it->second = static_cast<unsigned>(mesh.positions.size());
        mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
      }
      return it->second;
    };
    std::vector<glm::uvec3> finer;
    for (const glm::uvec3& tri : mesh.triangles) {
      const unsigned ab = midpoint(tri.x, tri.y), bc = midpoint(tri.y, tri.z),
                     ca = midpoint(tri.z, tri.x);
      finer.insert(finer.end(), {{tri.x, ab, ca}, {tri.y, bc, ab}, {tri.z, ca, bc}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(finer);
  }
  mesh.normals = mesh.positions;  // outward: nodes are seen from outside
  return mesh;
}

void appendNode(Mesh& mesh, const Mesh& unitSphere, glm::vec3 centre) {
  const auto base = static_cast<unsigned>(mesh.positions.size());
  for (std::size_t i = 0; i < unitSphere.positions.size(); ++i) {
    mesh.positions.push_back(centre + kNodeRadius * unitSphere.positions[i]);
    mesh.normals.push_back(unitSphere.normals[i]);
  }
  for (const glm::uvec3& tri : unitSphere.triangles) mesh.triangles.push_back(tri + base);
}

// An open triangular prism from a to b: three quads, radial normals.
void appendEdge(Mesh& mesh, glm::vec3 a, glm::vec3 b) {
  const glm::vec3 axis = glm::normalize(b - a);
  const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 side1 = glm::normalize(glm::cross(axis, helper));
  const glm::vec3 side2 = glm::cross(axis, side1);
  const auto base = static_cast<unsigned>(mesh.positions.size());
  for (int k = 0; k < 3; ++k) {
    const float angle = static_cast<float>(2.0 * std::numbers::pi * k / 3.0);
    const glm::vec3 radial = std::cos(angle) * side1 + std::sin(angle) * side2;
    mesh.positions.push_back(a + kEdgeRadius * radial);
    mesh.positions.push_back(b + kEdgeRadius * radial);
    mesh.normals.push_back(radial);
    mesh.normals.push_back(radial);
  }
  for (unsigned k = 0; k < 3; ++k) {
    const unsigned k2 = (k + 1) % 3;
    const glm::vec3 outward = mesh.normals[base + 2 * k] + mesh.normals[base + 2 * k2];
    builtin::addQuad(mesh, base + 2 * k, base + 2 * k2, base + 2 * k2 + 1, base + 2 * k + 1,
                     outward);
  }
}

glm::vec3 clusterColor(int cluster) {
  // Hues spread evenly around the colour wheel, full saturation (HSV -> RGB).
  const double h = 6.0 * cluster / kGraphClusters;
  const auto x = static_cast<float>(1.0 - std::abs(std::fmod(h, 2.0) - 1.0));
  const int sector = static_cast<int>(h);
  const glm::vec3 table[6] = {{1, x, 0}, {x, 1, 0}, {0, 1, x}, {0, x, 1}, {x, 0, 1}, {1, 0, x}};
  return table[sector % 6];
}

}  // namespace

namespace builtin {

Scene buildGraph(const BuiltinSceneOptions& options) {
  const int detail = optionOrDefault(options.subdivision, 2, "subdivision", "graph");
  if (detail > 5)
    throw Error(ErrorCode::InvalidInput, "built-in scene 'graph': subdivision (node detail) " +
                                             std::to_string(detail) + " exceeds 5");
  const Mesh unitSphere = unitIcosphere(detail - 1);
  Random random(kGraphSeed);
  Scene scene;

  std::vector<glm::dvec3> clusterCentres;
  std::vector<std::vector<glm::vec3>> nodes(kGraphClusters);
  for (int c = 0; c < kGraphClusters; ++c) {
    // Draws in named steps: operands and arguments are evaluated in an unspecified order (GCC
    // right to left, clang left to right), and the scene must not depend on the compiler. The
    // order is GCC's, which drew the stored goldens.
    const glm::dvec3 direction = random.direction();
    clusterCentres.push_back((5.0 + 7.0 * random.uniform()) * direction);
    for (int k = 0; k < kGraphNodesPerCluster; ++k) {
      const double z = random.normal(), y = random.normal(), x = random.normal();
      glm::dvec3 p = clusterCentres.back() + kClusterSpread * glm::dvec3(x, y, z);
      const double distance = std::clamp(glm::length(p), kMinDistance, kMaxDistance);
      nodes[static_cast<std::size_t>(c)].emplace_back(distance * glm::normalize(p));
    }
  }

  for (int c = 0; c < kGraphClusters; ++c) {
    const auto& members = nodes[static_cast<std::size_t>(c)];
    Mesh mesh;
    mesh.name = "cluster " + std::to_string(c);
    mesh.material = addMaterial(scene, mesh.name, clusterColor(c));
    for (const glm::vec3& p : members) appendNode(mesh, unitSphere, p);
    std::set<std::pair<std::size_t, std::size_t>> edges;
    for (std::size_t i = 0; i < members.size(); ++i) {
      std::vector<std::pair<float, std::size_t>> byDistance;
      for (std::size_t j = 0; j < members.size(); ++j)
        if (j != i) byDistance.emplace_back(glm::distance(members[i], members[j]), j);
      std::partial_sort(byDistance.begin(), byDistance.begin() + kNeighboursPerNode,
                        byDistance.end());
      for (int k = 0; k < kNeighboursPerNode; ++k)
        edges.insert(std::minmax(i, byDistance[static_cast<std::size_t>(k)].second));
    }
    for (const auto& [i, j] : edges) appendEdge(mesh, members[i], members[j]);
    scene.meshes.push_back(std::move(mesh));
  }

  Mesh links;
  links.name = "inter-cluster edges";
  links.material = addMaterial(scene, links.name, glm::vec3(0.8f));
  for (std::size_t c = 0; c < clusterCentres.size(); ++c) {
    std::vector<std::pair<double, std::size_t>> byDistance;
    for (std::size_t d = 0; d < clusterCentres.size(); ++d)
      if (d != c) byDistance.emplace_back(glm::distance(clusterCentres[c], clusterCentres[d]), d);
    std::partial_sort(byDistance.begin(), byDistance.begin() + kLinkedClusters, byDistance.end());
    for (int l = 0; l < kLinkedClusters; ++l) {
      const std::size_t d = byDistance[static_cast<std::size_t>(l)].second;
      for (int e = 0; e < kEdgesPerClusterLink; ++e) {
        const std::size_t to = random.index(nodes[d].size());
        const std::size_t from = random.index(nodes[c].size());
        appendEdge(links, nodes[c][from], nodes[d][to]);
      }
    }
  }
  scene.meshes.push_back(std::move(links));
  return scene;
}

}  // namespace builtin
}  // namespace confvis
