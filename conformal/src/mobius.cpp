#include "confvis/conformal/mobius.hpp"

#include <algorithm>
#include <cmath>

#include "confvis/base/error.hpp"

namespace confvis::conformal {

Mobius Mobius::operator*(const Mobius& g) const {
  return {a_ * g.a_ + b_ * g.c_, a_ * g.b_ + b_ * g.d_, c_ * g.a_ + d_ * g.c_,
          c_ * g.b_ + d_ * g.d_};
}

Mobius Mobius::crossRatio(Complex p, Complex q, Complex r) {
  return {r - q, -p * (r - q), r - p, -q * (r - p)};
}

Mobius Mobius::alignMarkers(Complex p, Complex q, Complex r) {
  const double minGap = std::min({std::abs(p - q), std::abs(q - r), std::abs(r - p)});
  if (!(minGap > 1e-12))
    throw Error(ErrorCode::InvalidInput, "Möbius alignment needs three distinct markers");
  // Orientation of the triangle p, q, r: 1, i, -1 is counter-clockwise.
  const double turn = ((q - p) * std::conj(r - p)).imag();
  if (!(turn < 0))
    throw Error(ErrorCode::InvalidInput,
                "Möbius alignment markers must be in counter-clockwise order along the boundary");
  const Complex i(0, 1);
  return crossRatio(1.0, i, -1.0).inverse() * crossRatio(p, q, r);
}

Mobius Mobius::diskAutomorphism(Complex a, double t) {
  if (!(std::abs(a) < 1))
    throw Error(ErrorCode::InvalidInput, "disk automorphism: the point sent to 0 must lie inside "
                                         "the unit disk");
  const Complex rotation = std::polar(1.0, t);
  return {rotation, -rotation * a, -std::conj(a), 1.0};
}

}  // namespace confvis::conformal
