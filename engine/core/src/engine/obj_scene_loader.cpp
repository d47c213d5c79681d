// Wavefront OBJ + MTL via tinyobjloader. OBJ indexes positions, normals and uvs separately;
// the renderers want one index per vertex, so each distinct (position, normal, uv) triple
// becomes one vertex. Faces are grouped into one Mesh per material.
#include <tiny_obj_loader.h>

#include <map>
#include <sstream>
#include <tuple>

#include "confvis/base/error.hpp"
#include "obj_text.hpp"
#include "scene_file_parts.hpp"

namespace confvis::scene_files {

namespace {

using Corner = std::tuple<int, int, int>;  // position, normal, uv index (-1 = absent)

struct MeshBuilder {
  Mesh mesh;
  std::map<Corner, unsigned> vertexOf;
  bool missingNormals = false;
};

void warnEachLine(const std::filesystem::path& path, const std::string& text) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) warn(path, line);
}

std::vector<Material> objMaterials(const std::filesystem::path& path,
                                   const std::vector<tinyobj::material_t>& source,
                                   std::vector<Texture>& textures) {
  std::vector<Material> materials;
  std::map<std::string, int> textureOf;  // a map_Kd used by several materials is read once
  for (const tinyobj::material_t& m : source) {
    Material material;
    material.name = restoredMaterialName(m.name);
    material.baseColorFactor = glm::vec4(m.diffuse[0], m.diffuse[1], m.diffuse[2], m.dissolve);
    if (!m.diffuse_texname.empty()) {
      const std::filesystem::path file = path.parent_path() / m.diffuse_texname;
      auto found = textureOf.find(file.string());
      if (found == textureOf.end()) {
        int index = -1;
        try {
          textures.push_back(loadTextureFile(file));
          index = static_cast<int>(textures.size()) - 1;
        } catch (const Error& error) {
          warn(path, "material '" + material.name + "': " + error.what() +
                         "; using its colour without the texture");
        }
        found = textureOf.emplace(file.string(), index).first;
      }
      material.baseColorTexture = found->second;
    }
    materials.push_back(material);
  }
  return materials;
}

}  // namespace

Scene loadObjScene(const std::filesystem::path& path) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  const ObjText text = prepareObjText(path);
  tinyobj::ObjReader reader;
  const bool ok = reader.ParseFromString(text.obj, text.mtl, config);
  if (!ok || !reader.Error().empty())
    throw Error(ErrorCode::InvalidInput, "cannot load OBJ file '" + path.string() + "': " +
                                             (reader.Error().empty() ? "parse failed"
                                                                     : reader.Error()));
  warnEachLine(path, reader.Warning());

  Scene scene;
  scene.name = path.filename().string();
  scene.materials = objMaterials(path, reader.GetMaterials(), scene.textures);

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto positionCount = static_cast<int>(attrib.vertices.size() / 3);
  const auto normalCount = static_cast<int>(attrib.normals.size() / 3);
  const auto uvCount = static_cast<int>(attrib.texcoords.size() / 2);
  std::map<int, MeshBuilder> builders;  // by material id; -1 = no material
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      const int materialId = shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids[face];
      MeshBuilder& builder = builders[materialId];
      glm::uvec3 triangle{};
      for (int corner = 0; corner < 3; ++corner) {
        const tinyobj::index_t& index = indices[3 * face + static_cast<std::size_t>(corner)];
        if (index.vertex_index < 0 || index.vertex_index >= positionCount ||
            index.normal_index >= normalCount || index.texcoord_index >= uvCount)
          throw Error(ErrorCode::InvalidInput, "OBJ file '" + path.string() + "', shape '" +
                                                   shape.name + "': face index out of range");
        const Corner key{index.vertex_index, index.normal_index, index.texcoord_index};
        auto [it, inserted] = builder.vertexOf.try_emplace(
            key, static_cast<unsigned>(builder.mesh.positions.size()));
        if (inserted) {
          const auto v = static_cast<std::size_t>(index.vertex_index);
          builder.mesh.positions.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                                              attrib.vertices[3 * v + 2]);
          const auto n = static_cast<std::size_t>(std::max(index.normal_index, 0));
          builder.missingNormals |= index.normal_index < 0;
          builder.mesh.normals.push_back(index.normal_index < 0
                                             ? glm::vec3(0.0f)
                                             : glm::vec3(attrib.normals[3 * n],
                                                         attrib.normals[3 * n + 1],
                                                         attrib.normals[3 * n + 2]));
          const auto t = static_cast<std::size_t>(std::max(index.texcoord_index, 0));
          // OBJ puts v = 0 at the image bottom; Texture follows glTF (v = 0 at the top).
          builder.mesh.uvs.push_back(index.texcoord_index < 0
                                         ? glm::vec2(0.0f)
                                         : glm::vec2(attrib.texcoords[2 * t],
                                                     1.0f - attrib.texcoords[2 * t + 1]));
        }
        triangle[corner] = it->second;
      }
      builder.mesh.triangles.push_back(triangle);
    }
  }
  for (auto& [materialId, builder] : builders) {
    builder.mesh.material = materialId;
    builder.mesh.name = materialId < 0 ? std::string("default material")
                                       : scene.materials[static_cast<std::size_t>(materialId)].name;
    if (builder.missingNormals) generateFlatNormals(builder.mesh);
    scene.meshes.push_back(std::move(builder.mesh));
  }
  return scene;
}

}  // namespace confvis::scene_files
