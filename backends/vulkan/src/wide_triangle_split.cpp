#include "wide_triangle_split.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace confvis::vulkan {
namespace {

// Corners closer than this to the centre (relative to the scene's own size) have no direction.
constexpr double kNoDirection = 1e-12;
// Bisections of one input triangle, at most (a safeguard: the edge counts end them far sooner).
constexpr int kMaxDepth = 48;

// Unit directions from `centre` to every position; zero where a position is at the centre.
std::vector<glm::dvec3> directionsFrom(const Mesh& mesh, const glm::dvec3& centre) {
  std::vector<glm::dvec3> directions;
  directions.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) {
    const glm::dvec3 d = glm::dvec3(p) - centre;
    const double length = glm::length(d);
    directions.push_back(length > kNoDirection * (1.0 + glm::length(centre)) ? d / length
                                                                              : glm::dvec3(0.0));
  }
  return directions;
}

class MeshSplitter {
 public:
  MeshSplitter(const Mesh& mesh, const glm::dvec3& centre, double maxRadians)
      : in_(mesh), out_(mesh), centre_(centre), maxRadians_(maxRadians) {
    out_.triangles.clear();
  }

  Mesh run(std::size_t& trianglesSplit) {
    for (const glm::uvec3& t : in_.triangles) {
      const std::size_t before = out_.triangles.size();
      split(t.x, t.y, t.z, 0);
      trianglesSplit += out_.triangles.size() - before > 1;
    }
    return std::move(out_);
  }

 private:
  static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
  }

  glm::dvec3 offset(std::uint32_t v) const { return glm::dvec3(out_.positions[v]) - centre_; }

  // The point at t along a -> b, every attribute interpolated linearly.
  std::uint32_t addPoint(std::uint32_t a, std::uint32_t b, double t) {
    const auto f = static_cast<float>(t);
    out_.positions.push_back(glm::mix(out_.positions[a], out_.positions[b], f));
    if (!out_.normals.empty()) out_.normals.push_back(glm::mix(out_.normals[a], out_.normals[b], f));
    if (!out_.uvs.empty()) out_.uvs.push_back(glm::mix(out_.uvs[a], out_.uvs[b], f));
    return static_cast<std::uint32_t>(out_.positions.size() - 1);
  }

  // The cut points of edge lo -> hi (lo < hi), both ends included: evenly spaced in the angle
  // the edge subtends at the centre, one piece per maxRadians_ of it.
  std::vector<std::uint32_t> cutEdge(std::uint32_t lo, std::uint32_t hi) {
    const glm::dvec3 a = offset(lo), b = offset(hi);
    const double la = glm::length(a), lb = glm::length(b);
    const double size = kNoDirection * (1.0 + glm::length(centre_));
    std::vector<std::uint32_t> points{lo};
    if (la > size && lb > size) {
      const double angle = std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
      const int pieces = std::clamp(static_cast<int>(std::ceil(angle / maxRadians_ - 1e-9)), 1,
                                    kMaxEdgePieces);
      for (int i = 1; i < pieces; ++i) {
        // The point of the chord seen at angle phi from a: t / (1 - t) = |a| sin phi /
        // (|b| sin(angle - phi)); an edge whose line passes through the centre is cut evenly.
        const double phi = angle * i / pieces;
        const double wa = la * std::sin(phi), wb = lb * std::sin(angle - phi);
        const double t = std::sin(angle) > 1e-9 && wa + wb > 0.0 ? wa / (wa + wb)
                                                                  : double(i) / pieces;
        points.push_back(addPoint(lo, hi, t));
      }
    }
    points.push_back(hi);
    return points;
  }

  // The cut points of a -> b in that order.
  std::vector<std::uint32_t> edge(std::uint32_t a, std::uint32_t b) {
    std::vector<std::uint32_t> points;
    if (const auto it = edges_.find(key(a, b)); it != edges_.end()) {
      points = it->second;
    } else {
      points = cutEdge(std::min(a, b), std::max(a, b));
      // An uncut edge comes out the same every time: only cut ones are kept.
      if (points.size() > 2) edges_.emplace(key(a, b), points);
    }
    if (a > b) std::reverse(points.begin(), points.end());
    return points;
  }

  // Records a -> b's cut points (given in that order) unless the edge is known.
  void setEdge(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t> points) {
    if (a > b) std::reverse(points.begin(), points.end());
    edges_.emplace(key(a, b), std::move(points));
  }

  void split(std::uint32_t a, std::uint32_t b, std::uint32_t c, int depth) {
    const std::uint32_t corners[3] = {a, b, c};
    std::vector<std::uint32_t> most;
    int first = -1;
    for (int k = 0; k < 3; ++k) {
      std::vector<std::uint32_t> points = edge(corners[k], corners[(k + 1) % 3]);
      if (points.size() > std::max<std::size_t>(2, most.size())) {
        most = std::move(points);
        first = k;
      }
    }
    if (first < 0 || depth >= kMaxDepth) {
      out_.triangles.push_back({a, b, c});
      return;
    }
    // Bisect at the most-cut edge x -> y's middle point m towards the opposite corner z (the
    // order x, y, z keeps the triangle's orientation).
    const std::uint32_t x = corners[first], y = corners[(first + 1) % 3], z = corners[(first + 2) % 3];
    const std::size_t middle = (most.size() - 1) / 2;
    const std::uint32_t m = most[middle];
    setEdge(x, m, {most.begin(), most.begin() + static_cast<std::ptrdiff_t>(middle) + 1});
    setEdge(m, y, {most.begin() + static_cast<std::ptrdiff_t>(middle), most.end()});
    split(x, m, z, depth + 1);
    split(m, y, z, depth + 1);
  }

  const Mesh& in_;
  Mesh out_;
  glm::dvec3 centre_;
  double maxRadians_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> edges_;
};

}  // namespace

bool hasWideTriangles(const Scene& scene, const glm::dvec3& centre, double maxDegrees) {
  const double minCosine = std::cos(glm::radians(maxDegrees));
  for (const Mesh& mesh : scene.meshes) {
    const std::vector<glm::dvec3> d = directionsFrom(mesh, centre);
    for (const glm::uvec3& t : mesh.triangles)
      if (glm::dot(d[t.x], d[t.y]) < minCosine || glm::dot(d[t.y], d[t.z]) < minCosine ||
          glm::dot(d[t.z], d[t.x]) < minCosine) {
        // A zero direction (a corner at the centre) gives a zero dot product: not apart.
        const auto apart = [&](std::uint32_t i, std::uint32_t j) {
          return d[i] != glm::dvec3(0.0) && d[j] != glm::dvec3(0.0) &&
                 glm::dot(d[i], d[j]) < minCosine;
        };
        if (apart(t.x, t.y) || apart(t.y, t.z) || apart(t.z, t.x)) return true;
      }
  }
  return false;
}

WideTriangleSplit splitWideTriangles(const Scene& scene, const glm::dvec3& centre,
                                     double maxDegrees) {
  WideTriangleSplit result;
  result.scene = scene;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    result.scene.meshes[i] = MeshSplitter(scene.meshes[i], centre, glm::radians(maxDegrees))
                                 .run(result.trianglesSplit);
  return result;
}

}  // namespace confvis::vulkan
