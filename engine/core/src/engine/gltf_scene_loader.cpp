// glTF 2.0 (.gltf, .glb) via tinygltf. Debian's TinyGLTF::TinyGLTF target is the shared
// library libtinygltf (implementation and stb included), so this file includes only the header.
// Node transforms are baked into each primitive: the renderers take world-space arrays.
#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/input_limits.hpp"
#include "gltf_file_checks.hpp"
#include "scene_file_parts.hpp"

namespace confvis::scene_files {

namespace {

constexpr int kModeTriangles = 4, kModeStrip = 5, kModeFan = 6;
constexpr const char* kDraco = "KHR_draco_mesh_compression";
constexpr const char* kTextureTransform = "KHR_texture_transform";

class GltfReader {
 public:
  GltfReader(const std::filesystem::path& path, const tinygltf::Model& model)
      : path_(path), model_(model) {}

  Scene read() {
    scene_.name = path_.filename().string();
    for (const std::string& extension : model_.extensionsRequired) requireSupported(extension);
    for (const tinygltf::Material& material : model_.materials) readMaterial(material);
    for (int root : rootNodes()) visitNode(root, glm::dmat4(1.0), 0);
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(ErrorCode::InvalidInput, "glTF file '" + path_.string() + "': " + message);
  }

  // Extensions a file may require that this reader honours; any other required one changes the
  // meaning of the data (compression, quantisation), so the file is refused rather than misread.
  void requireSupported(const std::string& extension) const {
    if (extension == kDraco)
      fail("Draco-compressed meshes (KHR_draco_mesh_compression) are not supported; export the "
           "model without Draco compression");
    if (extension != kTextureTransform)
      fail("requires the extension '" + extension + "', which confvis does not support");
  }

  std::vector<int> rootNodes() const {
    int sceneIndex = model_.defaultScene;
    if (sceneIndex < 0 && !model_.scenes.empty()) sceneIndex = 0;
    if (sceneIndex >= static_cast<int>(model_.scenes.size())) fail("scene index out of range");
    if (sceneIndex >= 0) return model_.scenes[static_cast<std::size_t>(sceneIndex)].nodes;
    // No scenes at all: every node that is nobody's child is a root.
    std::vector<bool> isChild(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes)
      for (int child : node.children)
        if (child >= 0 && child < static_cast<int>(isChild.size()))
          isChild[static_cast<std::size_t>(child)] = true;
    std::vector<int> roots;
    for (std::size_t i = 0; i < isChild.size(); ++i)
      if (!isChild[i]) roots.push_back(static_cast<int>(i));
    return roots;
  }

  static glm::dmat4 localTransform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3)
      m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1],
                                       node.translation[2]));
    if (node.rotation.size() == 4)
      m *= glm::mat4_cast(
          glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3)
      m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
  }

  void visitNode(int index, const glm::dmat4& parent, int depth) {
    if (index < 0 || index >= static_cast<int>(model_.nodes.size()))
      fail("node index " + std::to_string(index) + " out of range");
    if (depth > 256) fail("node hierarchy deeper than 256 (a cycle?)");
    // A node may be listed as a child many times (instancing): a small file could otherwise
    // make exponentially many copies.
    if (++nodeInstances_ > kMaxNodeInstances)
      fail("more than " + std::to_string(kMaxNodeInstances) +
           " node instances (nodes listed as children of several parents multiply)");
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 world = parent * localTransform(node);
    if (node.mesh >= 0) {
      if (node.mesh >= static_cast<int>(model_.meshes.size())) fail("mesh index out of range");
      const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(node.mesh)];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
        readPrimitive(mesh.primitives[p], mesh.name + " primitive " + std::to_string(p), world);
    }
    for (int child : node.children) visitNode(child, world, depth + 1);
  }

  const tinygltf::Accessor& accessor(int index, const std::string& what) const {
    if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
      fail(what + ": accessor index out of range");
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) fail(what + ": sparse accessors are not supported");
    return a;
  }

  // Pointers to each element of an accessor, bounds-checked against its buffer.
  std::vector<const unsigned char*> elements(const tinygltf::Accessor& a,
                                             const std::string& what) const {
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model_.bufferViews.size()))
      fail(what + ": accessor without a valid buffer view");
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model_.buffers.size()))
      fail(what + ": buffer index out of range");
    const std::vector<unsigned char>& data = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    const int stride = a.ByteStride(view);
    const int elementSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType)) *
                            tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (stride <= 0 || elementSize <= 0) fail(what + ": invalid accessor layout");
    // Offsets and counts come from the file: every sum and product is checked before it could
    // wrap (a byteOffset near 2^64 must not pass as a small one).
    if (!byteRangeFits(view.byteOffset, view.byteLength, data.size()))
      fail(what + ": buffer view " + std::to_string(a.bufferView) +
           " reaches past the end of its buffer");
    std::size_t span = 0;
    if (!stridedSpan(a.count, static_cast<std::size_t>(stride),
                     static_cast<std::size_t>(elementSize), span) ||
        !byteRangeFits(a.byteOffset, span, view.byteLength))
      fail(what + ": accessor reaches past the end of its buffer view");
    const std::size_t start = view.byteOffset + a.byteOffset;
    std::vector<const unsigned char*> result(a.count);
    for (std::size_t i = 0; i < a.count; ++i)
      result[i] = data.data() + start + i * static_cast<std::size_t>(stride);
    return result;
  }

  // Float vectors; normalized unsigned byte/short are accepted too (allowed for TEXCOORD_0).
  template <int N>
  std::vector<glm::vec<N, float>> readVectors(int index, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) != N)
      fail(what + ": expected " + std::to_string(N) + " components");
    std::vector<glm::vec<N, float>> result;
    for (const unsigned char* element : elements(a, what)) {
      glm::vec<N, float> v;
      for (int c = 0; c < N; ++c) {
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
          std::memcpy(&v[c], element + 4 * c, 4);
        } else if (a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
          v[c] = element[c] / 255.0f;
        } else if (a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
          std::uint16_t s;
          std::memcpy(&s, element + 2 * c, 2);
          v[c] = s / 65535.0f;
        } else {
          fail(what + ": unsupported component type " + std::to_string(a.componentType));
        }
      }
      result.push_back(v);
    }
    return result;
  }

  std::vector<unsigned> readIndices(int index, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    std::vector<unsigned> result;
    for (const unsigned char* element : elements(a, what)) {
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: result.push_back(*element); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          std::uint16_t s;
          std::memcpy(&s, element, 2);
          result.push_back(s);
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
          std::uint32_t u;
          std::memcpy(&u, element, 4);
          result.push_back(u);
          break;
        }
        default: fail(what + ": indices must be unsigned integers");
      }
    }
    return result;
  }

  static std::vector<glm::uvec3> assembleTriangles(const std::vector<unsigned>& idx, int mode) {
    std::vector<glm::uvec3> triangles;
    if (mode == kModeTriangles) {
      for (std::size_t i = 0; i + 2 < idx.size(); i += 3)
        triangles.emplace_back(idx[i], idx[i + 1], idx[i + 2]);
    } else if (mode == kModeStrip) {
      for (std::size_t i = 0; i + 2 < idx.size(); ++i)  // every other triangle is flipped
        triangles.push_back(i % 2 == 0 ? glm::uvec3(idx[i], idx[i + 1], idx[i + 2])
                                       : glm::uvec3(idx[i + 1], idx[i], idx[i + 2]));
    } else {  // fan
      for (std::size_t i = 1; i + 1 < idx.size(); ++i)
        triangles.emplace_back(idx[0], idx[i], idx[i + 1]);
    }
    return triangles;
  }

  void readPrimitive(const tinygltf::Primitive& primitive, const std::string& name,
                     const glm::dmat4& world) {
    const int mode = primitive.mode < 0 ? kModeTriangles : primitive.mode;
    if (mode != kModeTriangles && mode != kModeStrip && mode != kModeFan) {
      warn(path_, "skipping '" + name + "': not made of triangles (mode " + std::to_string(mode) + ")");
      return;
    }
    const auto attribute = [&](const char* key) {
      const auto it = primitive.attributes.find(key);
      return it == primitive.attributes.end() ? -1 : it->second;
    };
    if (primitive.extensions.count(kDraco))
      fail("'" + name + "' is Draco-compressed (KHR_draco_mesh_compression), which is not "
           "supported; export the model without Draco compression");
    if (attribute("POSITION") < 0) fail("'" + name + "' has no POSITION attribute");
    reserveSceneSize(name, accessor(attribute("POSITION"), name + " POSITION").count,
                     primitive.indices >= 0 ? accessor(primitive.indices, name + " indices").count
                                            : accessor(attribute("POSITION"), name).count);
    Mesh mesh;
    mesh.name = name;
    mesh.material = primitive.material;
    if (mesh.material >= static_cast<int>(scene_.materials.size())) fail(name + ": material out of range");
    mesh.positions = readVectors<3>(attribute("POSITION"), name + " POSITION");
    if (attribute("NORMAL") >= 0) mesh.normals = readVectors<3>(attribute("NORMAL"), name + " NORMAL");
    if (attribute("TEXCOORD_0") >= 0) mesh.uvs = readVectors<2>(attribute("TEXCOORD_0"), name + " TEXCOORD_0");
    // Every attribute has one value per vertex (found by fuzz_gltf: a short TEXCOORD_0 was read
    // past its end when flat normals were made).
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
      fail(name + ": NORMAL has " + std::to_string(mesh.normals.size()) + " values for " +
           std::to_string(mesh.positions.size()) + " positions");
    if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
      fail(name + ": TEXCOORD_0 has " + std::to_string(mesh.uvs.size()) + " values for " +
           std::to_string(mesh.positions.size()) + " positions");
    if (mesh.material >= 0)
      for (glm::vec2& uv : mesh.uvs)
        uv = glm::vec2(uvTransforms_[static_cast<std::size_t>(mesh.material)] * glm::vec3(uv, 1.0f));
    std::vector<unsigned> indices;
    if (primitive.indices >= 0) {
      indices = readIndices(primitive.indices, name + " indices");
    } else {
      for (unsigned i = 0; i < mesh.positions.size(); ++i) indices.push_back(i);
    }
    for (unsigned i : indices)
      if (i >= mesh.positions.size()) fail(name + ": vertex index out of range");
    mesh.triangles = assembleTriangles(indices, mode);

    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    for (glm::vec3& p : mesh.positions) p = glm::vec3(world * glm::dvec4(p, 1.0));
    for (glm::vec3& n : mesh.normals) n = glm::vec3(glm::normalize(normalMatrix * glm::dvec3(n)));
    if (glm::determinant(glm::dmat3(world)) < 0.0)  // mirroring flips the winding
      for (glm::uvec3& t : mesh.triangles) std::swap(t.y, t.z);
    if (mesh.normals.empty()) generateFlatNormals(mesh);
    scene_.meshes.push_back(std::move(mesh));
  }

  // Counts come from the file's accessors; the sum over every instance is bounded before any of
  // it is read (corners: each index may become a vertex of its own).
  void reserveSceneSize(const std::string& name, std::size_t vertices, std::size_t corners) {
    vertexTotal_ += vertices;
    cornerTotal_ += corners;
    if (vertexTotal_ > kMaxSceneVertices || cornerTotal_ / 3 > kMaxSceneTriangles)
      fail("'" + name + "' takes the scene past " + std::to_string(kMaxSceneVertices) +
           " vertices or " + std::to_string(kMaxSceneTriangles) + " triangles");
  }

  // KHR_texture_transform of a texture reference as the 3x3 matrix its README gives,
  // offset * rotation * scale, applied to TEXCOORD_0 at load.
  glm::mat3 uvTransform(const tinygltf::TextureInfo& info, const std::string& materialName) const {
    const auto found = info.extensions.find(kTextureTransform);
    if (found == info.extensions.end() || !found->second.IsObject()) return glm::mat3(1.0f);
    const tinygltf::Value& t = found->second;
    const auto pair = [&](const char* key, glm::vec2 fallback) {
      if (!t.Has(key)) return fallback;
      const tinygltf::Value& v = t.Get(key);
      if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
        fail("material '" + materialName + "': KHR_texture_transform '" + key +
             "' must be 2 numbers");
      return glm::vec2(static_cast<float>(v.Get(0).GetNumberAsDouble()),
                       static_cast<float>(v.Get(1).GetNumberAsDouble()));
    };
    const glm::vec2 offset = pair("offset", glm::vec2(0.0f)), scale = pair("scale", glm::vec2(1.0f));
    const float rotation = t.Has("rotation") && t.Get("rotation").IsNumber()
                               ? static_cast<float>(t.Get("rotation").GetNumberAsDouble())
                               : 0.0f;
    if (t.Has("texCoord") && t.Get("texCoord").IsNumber() && t.Get("texCoord").GetNumberAsInt() != 0)
      warn(path_, "material '" + materialName +
                      "': KHR_texture_transform asks for another TEXCOORD set; TEXCOORD_0 is used");
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 rotate(c, s, 0, -s, c, 0, 0, 0, 1);  // column-major, as in the README's GLSL
    const glm::mat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return translate * rotate * scaling;
  }

  void readMaterial(const tinygltf::Material& source) {
    Material material;
    material.name = source.name;
    const auto& pbr = source.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
      material.baseColorFactor = glm::vec4(glm::make_vec4(pbr.baseColorFactor.data()));
    if (pbr.baseColorTexture.index >= 0) {
      if (pbr.baseColorTexture.texCoord != 0)
        warn(path_, "material '" + source.name + "': base colour texture uses TEXCOORD_" +
                        std::to_string(pbr.baseColorTexture.texCoord) + "; TEXCOORD_0 is used");
      material.baseColorTexture = textureForImage(pbr.baseColorTexture.index, source.name);
    }
    uvTransforms_.push_back(uvTransform(pbr.baseColorTexture, source.name));
    scene_.materials.push_back(material);
  }

  int textureForImage(int textureIndex, const std::string& materialName) {
    if (textureIndex >= static_cast<int>(model_.textures.size())) fail("texture index out of range");
    const int image = model_.textures[static_cast<std::size_t>(textureIndex)].source;
    if (image < 0 || image >= static_cast<int>(model_.images.size())) fail("image index out of range");
    const auto found = textureOfImage_.find(image);
    if (found != textureOfImage_.end()) return found->second;
    const tinygltf::Image& source = model_.images[static_cast<std::size_t>(image)];
    int result = -1;
    if (source.image.empty() || source.width <= 0 || source.height <= 0) {
      warn(path_, "material '" + materialName + "': image '" + source.uri +
                      "' has no pixels; using the colour factor alone");
    } else {
      scene_.textures.push_back(textureFromPixels(source.image.data(), source.width, source.height,
                                                  source.component, source.bits, true));
      result = static_cast<int>(scene_.textures.size()) - 1;
    }
    textureOfImage_.emplace(image, result);
    return result;
  }

  const std::filesystem::path& path_;
  const tinygltf::Model& model_;
  Scene scene_;
  std::map<int, int> textureOfImage_;  // glTF image -> Scene texture (decoded once)
  std::vector<glm::mat3> uvTransforms_;  // per material: KHR_texture_transform of its texture
  std::size_t nodeInstances_ = 0, vertexTotal_ = 0, cornerTotal_ = 0;
};

}  // namespace

Scene loadGltfScene(const std::filesystem::path& path, bool binary) {
  const std::string bytes = readTextFile(path);
  if (bytes.size() > std::numeric_limits<unsigned>::max())
    throw Error(ErrorCode::InvalidInput, "glTF file '" + path.string() + "' is larger than 4 GiB");
  requireGltfJsonDepth(bytes, binary, path);
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  loader.SetImageLoader(&decodeGltfImage, &model);
  loader.SetFsCallbacks(gltfFileAccess());
  std::string error, warning;
  bool ok = false;
  const auto size = static_cast<unsigned>(bytes.size());
  const std::string baseDirectory = path.parent_path().string();
  try {  // tinygltf throws from its JSON parser and allocations; each names this file
    ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                              reinterpret_cast<const unsigned char*>(bytes.data()),
                                              size, baseDirectory)
                : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), size,
                                             baseDirectory);
  } catch (const std::exception& e) {
    throw Error(ErrorCode::InvalidInput,
                "cannot load glTF file '" + path.string() + "': " + e.what());
  }
  while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
  while (!warning.empty() && (warning.back() == '\n' || warning.back() == ' ')) warning.pop_back();
  if (!warning.empty()) warn(path, warning);
  if (!ok)
    throw Error(ErrorCode::InvalidInput, "cannot load glTF file '" + path.string() + "': " +
                                             (error.empty() ? "parse failed" : error));
  return GltfReader(path, model).read();
}

}  // namespace confvis::scene_files
