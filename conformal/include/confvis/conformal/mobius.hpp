#pragma once
// Möbius transformations z ↦ (az + b)/(cz + d), built from exact cross-ratios (dissertation
// §8.3.3, whose printed second map is garbled): alignMarkers(p, q, r) sends p, q, r to 1, i, -1;
// diskAutomorphism(a, t) = e^{it}(z - a)/(1 - conj(a) z) moves a to 0 and turns by t there.
#include <complex>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

using Complex = std::complex<double>;

// Thread-safety: an immutable value; call it from any number of threads at once.
class Mobius {
 public:
  Mobius() = default;  // identity
  Mobius(Complex a, Complex b, Complex c, Complex d) : a_(a), b_(b), c_(c), d_(d) {}

  Complex operator()(Complex z) const { return (a_ * z + b_) / (c_ * z + d_); }
  Mobius inverse() const { return {d_, -b_, -c_, a_}; }
  // (f * g)(z) = f(g(z))
  Mobius operator*(const Mobius& g) const;

  // Sends p, q, r to 0, ∞, 1: m(z) = ((z - p)(r - q)) / ((z - q)(r - p)).
  static Mobius crossRatio(Complex p, Complex q, Complex r);
  // Sends p, q, r to 1, i, -1. For p, q, r counter-clockwise on the unit circle the result maps
  // the unit disk onto itself; throws Error(InvalidInput) for clockwise or coincident markers.
  static Mobius alignMarkers(Complex p, Complex q, Complex r);
  // e^{it}(z - a)/(1 - conj(a) z): maps the unit disk onto itself, a to 0, with derivative
  // e^{it}/(1 - |a|^2) at a. Throws Error(InvalidInput) unless |a| < 1.
  static Mobius diskAutomorphism(Complex a, double t);

 private:
  Complex a_{1}, b_{0}, c_{0}, d_{1};
};

}  // namespace conformal
}  // namespace confvis
