#include "mesh_files.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/text_encoding.hpp"
#include "confvis/engine/number_text.hpp"

namespace confvis::conformal::detail {

namespace {

// Splits text into lines and lines into blank-separated words; numbers parse strictly.
class TextCursor {
 public:
  TextCursor(std::string text, std::filesystem::path path, std::string format)
      : text_(std::move(text)), path_(std::move(path)), format_(std::move(format)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(ErrorCode::InvalidInput, format_ + " file '" + path_.string() + "'" +
                                             (line_ > 0 ? ", line " + std::to_string(line_) : "") +
                                             ": " + what);
  }

  // The next line's words (comments from '#' dropped when `comments`); false at the end.
  bool nextLine(std::vector<std::string_view>& words, bool comments = true) {
    words.clear();
    while (position_ < text_.size()) {
      std::size_t end = text_.find('\n', position_);
      if (end == std::string::npos) end = text_.size();
      std::string_view line(text_.data() + position_, end - position_);
      position_ = end + 1;
      ++line_;
      if (comments) line = line.substr(0, line.find('#'));
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
      }
      if (!words.empty()) return true;
    }
    return false;
  }

  double number(std::string_view word, const char* what) const {
    const std::optional<double> value = confvis::detail::parseNumber(word);
    if (!value)
      fail(std::string("cannot read ") + what + " '" + std::string(word) + "' (a finite number)");
    return *value;
  }

  long long integer(std::string_view word, const char* what) const {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    long long value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || error != std::errc() || end != word.data() + word.size())
      fail(std::string("cannot read ") + what + " '" + std::string(word) + "' (an integer)");
    return value;
  }

  std::size_t count(std::string_view word, const char* what, std::size_t limit) const {
    const long long n = integer(word, what);
    if (n < 0 || static_cast<unsigned long long>(n) > limit)
      fail(std::string(what) + " " + std::to_string(n) + " is out of range (0.." +
           std::to_string(limit) + ")");
    return static_cast<std::size_t>(n);
  }

  std::size_t size() const { return text_.size(); }
  std::size_t position() const { return position_; }
  const std::string& text() const { return text_; }
  void seek(std::size_t position) { position_ = position; }

 private:
  std::string text_;
  std::filesystem::path path_;
  std::string format_;
  std::size_t position_ = 0, line_ = 0;
};

// Face corners: valence 3..kMaxFaceValence, indices inside the vertex list.
void addFace(PolygonSoup& soup, const std::vector<long long>& corners, const TextCursor& at) {
  if (corners.size() < 3 || corners.size() > kMaxFaceValence)
    at.fail("a face of " + std::to_string(corners.size()) + " corners (3.." +
            std::to_string(kMaxFaceValence) + ")");
  if (soup.starts.size() >= kMaxMeshFaces) at.fail("more than " + std::to_string(kMaxMeshFaces) + " faces");
  soup.starts.push_back(soup.corners.size());
  for (const long long v : corners) {
    if (v < 0 || static_cast<std::size_t>(v) >= soup.points.size())
      at.fail("face corner " + std::to_string(v) + " is not one of the " +
              std::to_string(soup.points.size()) + " vertices");
    soup.corners.push_back(static_cast<int>(v));
  }
}

void addPoint(PolygonSoup& soup, const std::array<double, 3>& p, const TextCursor& at) {
  if (soup.points.size() >= kMaxMeshVertices)
    at.fail("more than " + std::to_string(kMaxMeshVertices) + " vertices");
  soup.points.push_back(p);
}

// ---- OBJ ------------------------------------------------------------------------------------

PolygonSoup readObj(TextCursor& t) {
  PolygonSoup soup;
  std::vector<std::string_view> words;
  std::vector<long long> corners;
  while (t.nextLine(words)) {
    if (words[0] == "v") {
      const std::size_t n = words.size() - 1;
      if (n != 3 && n != 4 && n != 6 && n != 7)
        t.fail("a vertex needs 3 coordinates (4 with w, 6-7 with colour), got " + std::to_string(n));
      std::array<double, 3> p{};
      for (std::size_t i = 0; i < n; ++i) {
        const double x = t.number(words[i + 1], "vertex coordinate");
        if (i < 3) p[i] = x;
      }
      addPoint(soup, p, t);
    } else if (words[0] == "f") {
      corners.clear();
      for (std::size_t i = 1; i < words.size(); ++i) {
        const std::string_view index = words[i].substr(0, words[i].find('/'));
        const long long v = t.integer(index, "face corner");
        if (v == 0) t.fail("face corner 0 (OBJ counts from 1)");
        // Negative indices count back from the latest vertex.
        corners.push_back(v > 0 ? v - 1 : static_cast<long long>(soup.points.size()) + v);
      }
      addFace(soup, corners, t);
    }
  }
  return soup;
}

// ---- OFF ------------------------------------------------------------------------------------

PolygonSoup readOff(TextCursor& t) {
  PolygonSoup soup;
  std::vector<std::string_view> words;
  if (!t.nextLine(words)) t.fail("is empty");
  std::size_t first = 0;
  const std::string_view keyword = words[0];
  if (keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF") {
    if (keyword.find('4') != std::string_view::npos || keyword.front() == 'n')
      t.fail("'" + std::string(keyword) + "': only 3-D OFF files are supported");
    if (words.size() > 1 && words[1] == "BINARY") t.fail("binary OFF files are not supported");
    first = 1;
    if (words.size() == 1) {  // counts on a line of their own
      if (!t.nextLine(words)) t.fail("has no vertex and face counts");
      first = 0;
    }
  }
  if (words.size() < first + 2) t.fail("needs vertex and face counts");
  const std::size_t vertices = t.count(words[first], "vertex count", kMaxMeshVertices);
  const std::size_t faces = t.count(words[first + 1], "face count", kMaxMeshFaces);
  // Each vertex and face takes a line of at least 6 bytes: a count beyond that is a lie, and
  // nothing is reserved from it.
  soup.points.reserve(std::min(vertices, t.size() / 6));
  for (std::size_t i = 0; i < vertices; ++i) {
    if (!t.nextLine(words))
      t.fail("ends after " + std::to_string(i) + " of " + std::to_string(vertices) + " vertices");
    if (words.size() < 3) t.fail("a vertex needs 3 coordinates");
    addPoint(soup, {t.number(words[0], "vertex coordinate"), t.number(words[1], "vertex coordinate"),
                    t.number(words[2], "vertex coordinate")},
             t);
  }
  std::vector<long long> corners;
  for (std::size_t i = 0; i < faces; ++i) {
    if (!t.nextLine(words))
      t.fail("ends after " + std::to_string(i) + " of " + std::to_string(faces) + " faces");
    const std::size_t valence = t.count(words[0], "face valence", kMaxFaceValence);
    if (words.size() < valence + 1) t.fail("a face lists fewer corners than its valence");
    corners.clear();
    for (std::size_t c = 0; c < valence; ++c) corners.push_back(t.integer(words[c + 1], "face corner"));
    addFace(soup, corners, t);
  }
  return soup;
}

// ---- PLY ------------------------------------------------------------------------------------

enum class Encoding { Ascii, Little, Big };

struct PlyProperty {
  std::string name;
  int size = 0;          // bytes of the value (of each item for a list)
  bool isFloat = false;  // float/double versus integer
  bool isSigned = false;
  bool isList = false;
  int countSize = 0;     // list: bytes of the count
  bool countSigned = false;
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

bool plyType(std::string_view type, int& size, bool& isFloat, bool& isSigned) {
  static const std::map<std::string_view, std::tuple<int, bool, bool>> kTypes = {
      {"char", {1, false, true}},   {"int8", {1, false, true}},    {"uchar", {1, false, false}},
      {"uint8", {1, false, false}}, {"short", {2, false, true}},   {"int16", {2, false, true}},
      {"ushort", {2, false, false}}, {"uint16", {2, false, false}}, {"int", {4, false, true}},
      {"int32", {4, false, true}},  {"uint", {4, false, false}},   {"uint32", {4, false, false}},
      {"float", {4, true, true}},   {"float32", {4, true, true}},  {"double", {8, true, true}},
      {"float64", {8, true, true}}};
  const auto it = kTypes.find(type);
  if (it == kTypes.end()) return false;
  std::tie(size, isFloat, isSigned) = it->second;
  return true;
}

// Reads binary values, bounds-checked against the end of the file.
class ByteCursor {
 public:
  ByteCursor(const std::string& bytes, std::size_t position, bool bigEndian, const TextCursor& at)
      : bytes_(bytes), position_(position), bigEndian_(bigEndian), at_(at) {}

  double value(int size, bool isFloat, bool isSigned) {
    if (static_cast<std::size_t>(size) > bytes_.size() - position_) at_.fail("ends inside its data");
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + position_, static_cast<std::size_t>(size));
    position_ += static_cast<std::size_t>(size);
    if (bigEndian_ != (std::endian::native == std::endian::big)) std::reverse(raw, raw + size);
    if (isFloat) {
      if (size == 4) {
        float f;
        std::memcpy(&f, raw, 4);
        return f;
      }
      double d;
      std::memcpy(&d, raw, 8);
      return d;
    }
    std::uint64_t u = 0;
    std::memcpy(&u, raw, static_cast<std::size_t>(size));  // little-endian host
    if (isSigned && size < 8 && (u >> (8 * size - 1)) != 0) u |= ~std::uint64_t{0} << (8 * size);
    return isSigned ? static_cast<double>(static_cast<std::int64_t>(u)) : static_cast<double>(u);
  }

  std::size_t remaining() const { return bytes_.size() - position_; }

 private:
  const std::string& bytes_;
  std::size_t position_;
  bool bigEndian_;
  const TextCursor& at_;
};

PolygonSoup readPly(const std::string& bytes, TextCursor& t) {
  std::vector<std::string_view> words;
  if (!t.nextLine(words, false) || words.size() != 1 || words[0] != "ply") t.fail("does not start with 'ply'");
  Encoding encoding = Encoding::Ascii;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (!ended && t.nextLine(words, false)) {
    if (words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "format") {
      if (words.size() < 2) t.fail("format needs a name");
      if (words[1] == "ascii") encoding = Encoding::Ascii;
      else if (words[1] == "binary_little_endian") encoding = Encoding::Little;
      else if (words[1] == "binary_big_endian") encoding = Encoding::Big;
      else t.fail("unknown format '" + std::string(words[1]) + "'");
    } else if (words[0] == "element") {
      if (words.size() != 3) t.fail("'element' needs a name and a count");
      elements.push_back({std::string(words[1]), t.count(words[2], "element count", kMaxMeshFaces), {}});
    } else if (words[0] == "property") {
      if (elements.empty()) t.fail("'property' before any 'element'");
      PlyProperty p;
      if (words.size() == 5 && words[1] == "list") {
        p.isList = true;
        bool countFloat = false;
        if (!plyType(words[2], p.countSize, countFloat, p.countSigned) || countFloat)
          t.fail("a list count must be an integer type, got '" + std::string(words[2]) + "'");
        if (!plyType(words[3], p.size, p.isFloat, p.isSigned))
          t.fail("unknown type '" + std::string(words[3]) + "'");
        p.name = words[4];
      } else if (words.size() == 3) {
        if (!plyType(words[1], p.size, p.isFloat, p.isSigned))
          t.fail("unknown type '" + std::string(words[1]) + "'");
        p.name = words[2];
      } else {
        t.fail("malformed property line");
      }
      elements.back().properties.push_back(p);
    } else if (words[0] == "end_header") {
      ended = true;
    } else {
      t.fail("unknown header line '" + std::string(words[0]) + "'");
    }
  }
  if (!ended) t.fail("has no end_header");

  PolygonSoup soup;
  const std::size_t dataStart = std::min(t.position(), bytes.size());
  ByteCursor binary(bytes, dataStart, encoding == Encoding::Big, t);
  std::vector<double> values;
  std::vector<long long> corners;
  for (const PlyElement& element : elements) {
    const bool isVertex = element.name == "vertex", isFace = element.name == "face";
    int x = -1, y = -1, z = -1, list = -1;
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
      const PlyProperty& p = element.properties[i];
      if (p.isList && list < 0 && (p.name == "vertex_indices" || p.name == "vertex_index" || isFace))
        list = static_cast<int>(i);
      if (!p.isList) {
        if (p.name == "x") x = static_cast<int>(i);
        if (p.name == "y") y = static_cast<int>(i);
        if (p.name == "z") z = static_cast<int>(i);
      }
    }
    if (isVertex && (x < 0 || y < 0 || z < 0)) t.fail("element vertex lacks x, y or z");
    if (isVertex && element.count > kMaxMeshVertices)
      t.fail("more than " + std::to_string(kMaxMeshVertices) + " vertices");
    if (isFace && list < 0) t.fail("element face has no vertex_indices list");
    // An element's items take at least one byte each (ascii: two): counts beyond the file are
    // refused before anything is reserved.
    if (element.count > bytes.size()) t.fail("element " + element.name + " count exceeds the file size");
    if (isVertex) soup.points.reserve(element.count);
    for (std::size_t item = 0; item < element.count; ++item) {
      std::array<double, 3> point{};
      corners.clear();
      std::size_t word = 0;
      if (encoding == Encoding::Ascii && !t.nextLine(words, false))
        t.fail("ends inside element " + element.name);
      const auto next = [&](int size, bool isFloat, bool isSigned) -> double {
        if (encoding != Encoding::Ascii) {
          const double v = binary.value(size, isFloat, isSigned);
          if (!std::isfinite(v)) t.fail("a non-finite value in element " + element.name);
          return v;
        }
        if (word >= words.size()) t.fail("a line of element " + element.name + " is too short");
        return isFloat ? t.number(words[word++], "value")
                       : static_cast<double>(t.integer(words[word++], "integer"));
      };
      for (std::size_t i = 0; i < element.properties.size(); ++i) {
        const PlyProperty& p = element.properties[i];
        if (!p.isList) {
          const double v = next(p.size, p.isFloat, p.isSigned);
          if (static_cast<int>(i) == x) point[0] = v;
          if (static_cast<int>(i) == y) point[1] = v;
          if (static_cast<int>(i) == z) point[2] = v;
          continue;
        }
        const double n = next(p.countSize, false, p.countSigned);
        if (n < 0 || n > static_cast<double>(kMaxFaceValence))
          t.fail("a list of " + std::to_string(static_cast<long long>(n)) + " items (0.." +
                 std::to_string(kMaxFaceValence) + ")");
        for (int k = 0; k < static_cast<int>(n); ++k) {
          const double v = next(p.size, p.isFloat, p.isSigned);
          if (static_cast<int>(i) == list) corners.push_back(static_cast<long long>(v));
        }
      }
      if (isVertex) addPoint(soup, point, t);
      if (isFace) addFace(soup, corners, t);
    }
  }
  return soup;
}

// ---- STL ------------------------------------------------------------------------------------

// STL repeats each vertex in every facet: equal positions become one vertex.
class VertexMerger {
 public:
  int index(PolygonSoup& soup, const std::array<double, 3>& p, const TextCursor& at) {
    for (const double c : p)
      if (!std::isfinite(c)) at.fail("a facet has a non-finite (NaN or infinite) vertex");
    std::array<std::uint64_t, 3> key;
    for (int i = 0; i < 3; ++i) key[static_cast<std::size_t>(i)] = std::bit_cast<std::uint64_t>(p[static_cast<std::size_t>(i)] + 0.0);
    const auto [it, inserted] = known_.try_emplace(key, static_cast<int>(soup.points.size()));
    if (inserted) addPoint(soup, p, at);
    return it->second;
  }

 private:
  std::map<std::array<std::uint64_t, 3>, int> known_;
};

PolygonSoup readStl(const std::string& bytes, TextCursor& t) {
  PolygonSoup soup;
  VertexMerger merger;
  std::uint32_t count = 0;
  if (bytes.size() >= 84) std::memcpy(&count, bytes.data() + 80, 4);
  if (bytes.size() >= 84 && 84 + 50 * static_cast<std::uint64_t>(count) == bytes.size()) {
    if (count > kMaxMeshFaces) t.fail("more than " + std::to_string(kMaxMeshFaces) + " facets");
    for (std::uint32_t f = 0; f < count; ++f) {
      const char* facet = bytes.data() + 84 + 50 * static_cast<std::size_t>(f);
      std::vector<long long> corners;
      for (int v = 0; v < 3; ++v) {
        float xyz[3];
        std::memcpy(xyz, facet + 12 + 12 * v, 12);
        corners.push_back(merger.index(soup, {xyz[0], xyz[1], xyz[2]}, t));
      }
      addFace(soup, corners, t);
    }
    return soup;
  }
  std::vector<std::string_view> words;
  if (!t.nextLine(words, false) || words[0] != "solid")
    t.fail("is neither binary STL (84 + 50 bytes per facet) nor ASCII STL ('solid ...')");
  std::vector<long long> corners;
  while (t.nextLine(words, false)) {
    if (words[0] == "vertex") {
      if (words.size() != 4) t.fail("'vertex' needs 3 coordinates");
      corners.push_back(merger.index(soup, {t.number(words[1], "vertex coordinate"),
                                            t.number(words[2], "vertex coordinate"),
                                            t.number(words[3], "vertex coordinate")},
                                     t));
    } else if (words[0] == "endloop") {
      addFace(soup, corners, t);
      corners.clear();
    }
  }
  return soup;
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

}  // namespace

PolygonSoup readPolygonFile(const std::filesystem::path& path) {
  const std::string extension = lowerExtension(path);
  if (extension != ".obj" && extension != ".off" && extension != ".ply" && extension != ".stl")
    throw Error(ErrorCode::InvalidInput, "mesh file '" + path.string() +
                                             "': unknown extension (OBJ, OFF, PLY and STL are "
                                             "supported)");
  const std::string bytes = readTextFile(path);
  if (extension == ".ply") {
    TextCursor header(bytes, path, "PLY");
    // The header is text; the data may be binary. Read the header alone first.
    const std::size_t end = bytes.find("end_header");
    if (end == std::string::npos) header.fail("has no end_header");
    if (bytes.find("format ascii") < end) {
      TextCursor text(decodeTextFile(bytes, path), path, "PLY");
      return readPly(text.text(), text);
    }
    return readPly(bytes, header);
  }
  if (extension == ".stl") {
    TextCursor t(bytes.size() >= 84 ? bytes : decodeTextFile(bytes, path), path, "STL");
    return readStl(t.text(), t);
  }
  TextCursor t(decodeTextFile(bytes, path), path, extension == ".obj" ? "OBJ" : "OFF");
  return extension == ".obj" ? readObj(t) : readOff(t);
}

}  // namespace confvis::conformal::detail
