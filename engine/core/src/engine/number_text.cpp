#include "confvis/engine/number_text.hpp"

#include <charconv>
#include <cmath>
#include <vector>

namespace confvis::detail {

std::optional<double> parseNumber(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);  // from_chars rejects '+'
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::optional<glm::dvec3> parseTriple(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t start = text.find_first_not_of(" \t\r\n", i);
    if (start == std::string_view::npos) break;
    const std::size_t end = std::min(text.find_first_of(" \t\r\n", start), text.size());
    tokens.push_back(text.substr(start, end - start));
    i = end;
  }
  if (tokens.size() != 3) return std::nullopt;
  glm::dvec3 v;
  for (int k = 0; k < 3; ++k) {
    const std::optional<double> x = parseNumber(tokens[k]);
    if (!x) return std::nullopt;
    v[k] = *x;
  }
  return v;
}

}  // namespace confvis::detail
