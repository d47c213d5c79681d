#pragma once
// OpenEXR input/output for RGBA images: single images, stereo pairs (OpenEXR multi-view), and,
// in cube_map.hpp, cube environment maps. Files are written atomically, ZIP-compressed, with
// channels R, G, B, A. Writers throw Error naming the file rather than store NaN or infinity.
#include <filesystem>
#include <utility>

#include "confvis/base/export.hpp"
#include "confvis/base/image.hpp"

namespace confvis CONFVIS_API {

// Storage type in the file. Half is enough for colour; maps of directions need Float
// (half quantises directions to ~0.03 degrees, close to a CAVE pixel).
enum class ExrPixel { Float, Half };

// Throws Error(InvalidInput) for empty or non-finite images, and for Half when a value exceeds
// half's range (it would be stored as infinity); Error(IoFailure) when writing fails.
void writeExr(const std::filesystem::path& path, const ImageRGBA& image,
              ExrPixel pixel = ExrPixel::Float);

// Reads R, G, B and (if present, else 1) A of any scanline or tiled EXR, whatever its data
// window origin. Throws Error(FileNotFound) for a missing file, Error(IoFailure) for a corrupt
// or truncated one or one without R, G, B channels; messages name the file.
ImageRGBA readExr(const std::filesystem::path& path);

// Stereo pair in one file, following the OpenEXR multi-view convention: attribute
// multiView = ["left", "right"]; the default (first) view "left" has unprefixed channels
// R, G, B, A, the other view has channels right.R, right.G, right.B, right.A. Viewers and
// compositors that know multi-view show both eyes; others show the left eye. Float32.
void writeStereoExr(const std::filesystem::path& path, const ImageRGBA& left,
                    const ImageRGBA& right);

// Returns {left, right}. Views are found by name ("left"/"right"), falling back to the first two
// views of the multiView attribute; throws Error(IoFailure) if the file is not multi-view.
std::pair<ImageRGBA, ImageRGBA> readStereoExr(const std::filesystem::path& path);

}  // namespace confvis
