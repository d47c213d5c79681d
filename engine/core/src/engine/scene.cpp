#include "confvis/engine/scene.hpp"

#include <cmath>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

int wrapIndex(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

std::string meshLabel(const Scene& scene, std::size_t meshIndex) {
  const Mesh& mesh = scene.meshes[meshIndex];
  return "scene '" + scene.name + "', mesh " + std::to_string(meshIndex) +
         (mesh.name.empty() ? "" : " ('" + mesh.name + "')");
}

}  // namespace

glm::vec4 Texture::texel(int x, int y) const {
  const std::size_t i =
      4 * (static_cast<std::size_t>(wrapIndex(y, height)) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(wrapIndex(x, width)));
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

namespace {

// The texel column (row) of a footprint at continuous coordinate x, texel centres at integers:
// floor(x) and the fraction past it, floor(x) wrapped into [0, n) and the next one wrapped.
struct WrappedAxis {
  int first = 0, second = 0;
  float fraction = 0.0f;
};

// What the general rule below gives, by integer arithmetic: floor as a truncation corrected by
// one, fmod of an integer-valued double as the integer remainder (both exact below 2^62). About
// 1 % of a frame's texture footprints cross a border and land here, and floor, fmod and four
// integer divisions per texel made them cost ~100 ns each.
bool wrapExactly(double x, int n, WrappedAxis& out) {
  if (!(std::abs(x) < 0x1p62)) return false;  // NaN and huge coordinates: the general rule
  auto x0 = static_cast<long long>(x);        // truncated towards zero
  if (static_cast<double>(x0) > x) --x0;      // floor
  out.fraction = static_cast<float>(x - static_cast<double>(x0));
  out.first = wrapIndex(static_cast<int>(x0 % n), n);
  out.second = out.first + 1 == n ? 0 : out.first + 1;
  return true;
}

}  // namespace

glm::vec4 Texture::sampleWrapped(glm::vec2 uv) const {
  if (width <= 0 || height <= 0) return glm::vec4(1.0f);
  // Continuous texel coordinates with texel centres at integers.
  const double x = static_cast<double>(uv.x) * width - 0.5;
  const double y = static_cast<double>(uv.y) * height - 0.5;
  WrappedAxis column, row;
  if (wrapExactly(x, width, column) && wrapExactly(y, height, row)) {
    const auto at = [this](int i, int j) {
      const std::size_t k =
          4 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(i));
      return glm::vec4(rgba[k], rgba[k + 1], rgba[k + 2], rgba[k + 3]);
    };
    const glm::vec4 top = glm::mix(at(column.first, row.first), at(column.second, row.first),
                                   column.fraction);
    const glm::vec4 bottom = glm::mix(at(column.first, row.second),
                                      at(column.second, row.second), column.fraction);
    return glm::mix(top, bottom, row.fraction);
  }
  const double x0 = std::floor(x);
  const double y0 = std::floor(y);
  const auto fx = static_cast<float>(x - x0);
  const auto fy = static_cast<float>(y - y0);
  // Reduce before converting so huge repeat counts cannot overflow int.
  const int ix = wrapIndex(static_cast<int>(std::fmod(x0, width)), width);
  const int iy = wrapIndex(static_cast<int>(std::fmod(y0, height)), height);
  const glm::vec4 top = glm::mix(texel(ix, iy), texel(ix + 1, iy), fx);
  const glm::vec4 bottom = glm::mix(texel(ix, iy + 1), texel(ix + 1, iy + 1), fx);
  return glm::mix(top, bottom, fy);
}

glm::vec4 Scene::baseColorAt(std::size_t meshIndex, std::size_t triangle,
                             glm::vec2 barycentrics) const {
  const Mesh& mesh = meshes.at(meshIndex);
  if (mesh.material < 0) return glm::vec4(1.0f);
  const Material& material = materials.at(static_cast<std::size_t>(mesh.material));
  if (material.baseColorTexture < 0 || mesh.uvs.empty()) return material.baseColorFactor;
  const glm::uvec3 tri = mesh.triangles.at(triangle);
  const glm::vec2 uv = (1.0f - barycentrics.x - barycentrics.y) * mesh.uvs[tri.x] +
                       barycentrics.x * mesh.uvs[tri.y] + barycentrics.y * mesh.uvs[tri.z];
  const Texture& texture = textures.at(static_cast<std::size_t>(material.baseColorTexture));
  return material.baseColorFactor * texture.sample(uv);
}

std::size_t Scene::triangleCount() const {
  std::size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.triangles.size();
  return count;
}

std::size_t Scene::vertexCount() const {
  std::size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.positions.size();
  return count;
}

Bounds Scene::bounds() const {
  Bounds box;
  for (const Mesh& mesh : meshes)
    for (const glm::vec3& p : mesh.positions) box.extend(p);
  return box;
}

void validateScene(const Scene& scene) {
  if (scene.triangleCount() == 0)
    throw Error(ErrorCode::InvalidInput, "scene '" + scene.name + "' contains no triangles");
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const Texture& texture = scene.textures[t];
    if (texture.width <= 0 || texture.height <= 0 ||
        texture.rgba.size() != 4 * static_cast<std::size_t>(texture.width) *
                                   static_cast<std::size_t>(texture.height))
      throw Error(ErrorCode::InvalidInput, "scene '" + scene.name + "', texture " +
                                               std::to_string(t) + ": size does not match pixels");
  }
  for (const Material& material : scene.materials)
    if (material.baseColorTexture >= static_cast<int>(scene.textures.size()))
      throw Error(ErrorCode::InvalidInput, "scene '" + scene.name + "', material '" +
                                               material.name + "': texture index out of range");
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const std::size_t n = mesh.positions.size();
    if (!mesh.normals.empty() && mesh.normals.size() != n)
      throw Error(ErrorCode::InvalidInput, meshLabel(scene, m) + ": normal count differs");
    if (!mesh.uvs.empty() && mesh.uvs.size() != n)
      throw Error(ErrorCode::InvalidInput, meshLabel(scene, m) + ": uv count differs");
    if (mesh.material >= static_cast<int>(scene.materials.size()))
      throw Error(ErrorCode::InvalidInput, meshLabel(scene, m) + ": material out of range");
    for (const glm::uvec3& tri : mesh.triangles)
      if (tri.x >= n || tri.y >= n || tri.z >= n)
        throw Error(ErrorCode::InvalidInput, meshLabel(scene, m) + ": vertex index out of range");
    for (const glm::vec3& p : mesh.positions)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw Error(ErrorCode::InvalidInput, meshLabel(scene, m) + ": non-finite position");
  }
}

void generateFlatNormals(Mesh& mesh) {
  Mesh flat;
  flat.name = mesh.name;
  flat.material = mesh.material;
  const bool hasUvs = !mesh.uvs.empty();
  for (const glm::uvec3& tri : mesh.triangles) {
    const glm::vec3 a = mesh.positions[tri.x], b = mesh.positions[tri.y], c = mesh.positions[tri.z];
    const glm::vec3 cross = glm::cross(b - a, c - a);
    const float length = glm::length(cross);
    // Degenerate triangles get an arbitrary unit normal rather than NaN.
    const glm::vec3 normal = length > 0.0f ? cross / length : glm::vec3(0.0f, 0.0f, 1.0f);
    const auto base = static_cast<unsigned>(flat.positions.size());
    for (unsigned corner = 0; corner < 3; ++corner) {
      flat.positions.push_back(mesh.positions[tri[static_cast<int>(corner)]]);
      flat.normals.push_back(normal);
      if (hasUvs) flat.uvs.push_back(mesh.uvs[tri[static_cast<int>(corner)]]);
    }
    flat.triangles.emplace_back(base, base + 1, base + 2);
  }
  mesh = std::move(flat);
}

}  // namespace confvis
