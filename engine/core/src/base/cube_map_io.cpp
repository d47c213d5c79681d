// Cube maps as OpenEXR environment maps and as cross-shaped PNG previews.
#include <ImfChannelList.h>
#include <ImfStandardAttributes.h>

#include <algorithm>
#include <string>

#include "confvis/base/cube_map.hpp"
#include "confvis/base/error.hpp"
#include "exr_internal.hpp"

namespace confvis {
namespace fs = std::filesystem;

namespace {

void copyBlock(const ImageRGBA& from, int fromY, ImageRGBA& to, int toX, int toY, int size) {
  for (int y = 0; y < size; ++y) std::copy_n(from.at(0, fromY + y), 4 * size, to.at(toX, toY + y));
}

// Shape only: the image writers reject NaN and infinity themselves, naming the file.
void requireSquareFaces(const CubeMap& map, const std::string& context) {
  const int n = map.faceSize;
  for (const ImageRGBA& f : map.faces)
    if (n <= 0 || f.width != n || f.height != n || f.pixels.size() != f.pixelCount() * 4)
      throw Error(ErrorCode::InvalidInput,
                  context + ": cube map faces are not all " + std::to_string(n) + "x" +
                      std::to_string(n));
}

// The OpenEXR cube layout: N x 6N, faces in CubeFace order from the top.
ImageRGBA stackFaces(const CubeMap& map) {
  const int n = map.faceSize;
  ImageRGBA stacked(n, 6 * n);
  for (CubeFace face : kCubeFaces)
    copyBlock(map.face(face), 0, stacked, 0, static_cast<int>(face) * n, n);
  return stacked;
}

}  // namespace

void writeCubeExr(const fs::path& path, const CubeMap& map) {
  requireSquareFaces(map, "refusing to write '" + path.string() + "'");
  const ImageRGBA stacked = stackFaces(map);
  detail::writeExrLayers(path, {{"", &stacked}}, ExrPixel::Float,
                         [](Imf::Header& header) { Imf::addEnvmap(header, Imf::ENVMAP_CUBE); });
}

CubeMap readCubeExr(const fs::path& path) {
  ImageRGBA stacked;
  detail::withExrInput(path, [&](Imf::InputFile& file) {
    if (!Imf::hasEnvmap(file.header()) || Imf::envmap(file.header()) != Imf::ENVMAP_CUBE)
      throw Error(ErrorCode::IoFailure,
                  "EXR file '" + path.string() + "' is not a cube environment map (envmap = cube)");
    // Cube maps hold directions in float32 (writeCubeExr): any other pixel type is a damaged
    // or foreign file whose texels would be converted into wrong directions.
    for (auto channel = file.header().channels().begin(); channel != file.header().channels().end();
         ++channel)
      if (channel.channel().type != Imf::FLOAT)
        throw Error(ErrorCode::IoFailure, "cube map '" + path.string() + "': channel '" +
                                              channel.name() +
                                              "' is not float32 (a damaged or foreign file)");
    stacked = detail::readExrLayer(file, path, "");
  });
  if (stacked.width <= 0 || stacked.height != 6 * stacked.width)
    throw Error(ErrorCode::IoFailure, "cube map '" + path.string() + "' is " +
                                          std::to_string(stacked.width) + "x" +
                                          std::to_string(stacked.height) + ", expected N x 6N");
  const int n = stacked.width;
  CubeMap map(n);
  for (CubeFace face : kCubeFaces)
    copyBlock(stacked, static_cast<int>(face) * n, map.face(face), 0, 0, n);
  return map;
}

ImageRGBA cubeCrossImage(const CubeMap& map) {
  requireSquareFaces(map, "cube-cross preview");
  const int n = map.faceSize;
  struct Cell {
    CubeFace face;
    int column, row;
  };
  // Faces are stored as seen from inside the cube with the seams of this cross matching, so
  // placing them unchanged gives a continuous panorama around a viewer facing -z.
  constexpr Cell kCells[] = {{CubeFace::PosY, 1, 0}, {CubeFace::NegX, 0, 1},
                             {CubeFace::NegZ, 1, 1}, {CubeFace::PosX, 2, 1},
                             {CubeFace::PosZ, 3, 1}, {CubeFace::NegY, 1, 2}};
  ImageRGBA cross(4 * n, 3 * n, 0.0f);
  for (const Cell& cell : kCells)
    copyBlock(map.face(cell.face), 0, cross, cell.column * n, cell.row * n, n);
  return cross;
}

void writeCubeCrossPng(const fs::path& path, const CubeMap& map, const PngOptions& options) {
  requireSquareFaces(map, "refusing to write '" + path.string() + "'");
  writePng(path, cubeCrossImage(map), options);
}

}  // namespace confvis
