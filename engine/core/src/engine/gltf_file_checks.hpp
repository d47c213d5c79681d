#pragma once
// Checks on glTF input that tinygltf does not make itself (private to the glTF loader): nesting
// of the JSON before tinygltf's recursive code sees it, and image decoding with the buffer view
// bounds-checked and the pixel count bounded before anything is allocated.
#include <filesystem>
#include <string>

#include <tiny_gltf.h>

namespace confvis::scene_files {

// Throws Error(InvalidInput) naming `path` when the JSON of a .gltf (the text) or a .glb (its
// first chunk) nests deeper than kMaxJsonDepth.
void requireGltfJsonDepth(const std::string& bytes, bool binary, const std::filesystem::path& path);

// tinygltf's LoadImageDataFunction; `user` is the tinygltf::Model being loaded (its buffers and
// buffer views are read before its images).
bool decodeGltfImage(tinygltf::Image* image, int index, std::string* error, std::string* warning,
                     int requiredWidth, int requiredHeight, const unsigned char* bytes, int size,
                     void* user);

// File access for tinygltf (its FsCallbacks): only regular files are read (a URI naming a
// directory made tinygltf allocate SIZE_MAX bytes), and none larger than 4 GiB.
tinygltf::FsCallbacks gltfFileAccess();

}  // namespace confvis::scene_files
