#pragma once
// Scene files: Wavefront OBJ (+ MTL) and glTF 2.0 (.gltf, .glb), turned into the shared Scene.
//
// Decisions:
// - A missing .mtl file or texture image is not fatal: a warning goes to stderr and the mesh
//   keeps a white material (or its Kd colour without the texture). Geometry is what a
//   conformal-map check needs; a broken material reference should not stop a CAVE session.
// - Everything else that is wrong is an Error naming the file: missing file (FileNotFound),
//   unknown extension, malformed file (the parser's message included), no triangles.
// - Textures are decoded to linear RGBA floats (8-bit images are treated as sRGB, as glTF and
//   common OBJ practice specify for base colour); OBJ texture v is flipped to the glTF
//   convention of Texture. glTF node transforms are baked into the positions and normals.
#include <filesystem>
#include <string>

#include "confvis/base/export.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis CONFVIS_API {

// Dispatches by extension (case-insensitive): .obj, .gltf, .glb.
Scene loadScene(const std::filesystem::path& path);

// A built-in scene name (see builtinSceneNames()) or else a scene file path.
Scene sceneByNameOrFile(const std::string& nameOrPath);

}  // namespace confvis
