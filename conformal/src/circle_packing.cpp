#include "confvis/conformal/circle_packing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "confvis/base/error.hpp"

namespace confvis::conformal {

const char* toString(Geometry g) noexcept {
  switch (g) {
    case Geometry::Euclidean: return "euclidean";
    case Geometry::Hyperbolic: return "hyperbolic";
    case Geometry::Spherical: return "spherical";
  }
  return "?";
}

const char* toString(Scheme s) noexcept {
  switch (s) {
    case Scheme::Tangential: return "tangential";
    case Scheme::Thurston: return "thurston";
    case Scheme::InversiveDistance: return "inversive";
    case Scheme::Yamabe: return "yamabe";
    case Scheme::VirtualRadius: return "virtual";
    case Scheme::Mixed: return "mixed";
  }
  return "?";
}

Geometry parseGeometry(const std::string& name) {
  for (Geometry g : kAllGeometries)
    if (name == toString(g)) return g;
  throw Error(ErrorCode::InvalidInput,
              "unknown geometry '" + name + "' (expected euclidean, hyperbolic or spherical)");
}

Scheme parseScheme(const std::string& name) {
  for (Scheme s : kAllSchemes)
    if (name == toString(s)) return s;
  throw Error(ErrorCode::InvalidInput,
              "unknown scheme '" + name +
                  "' (expected tangential, thurston, inversive, yamabe, virtual or mixed)");
}

double conformalFactorFromRadius(Geometry g, double r) {
  switch (g) {
    case Geometry::Euclidean: return std::log(r);
    case Geometry::Hyperbolic: return std::log(std::tanh(r / 2));
    case Geometry::Spherical: return std::log(std::tan(r / 2));
  }
  return 0;
}

double radiusFromConformalFactor(Geometry g, double u) {
  switch (g) {
    case Geometry::Euclidean: return std::exp(u);
    case Geometry::Hyperbolic: return 2 * std::atanh(std::exp(u));
    case Geometry::Spherical: return 2 * std::atan(std::exp(u));
  }
  return 0;
}

double backgroundCurvature(Geometry g) noexcept {
  return g == Geometry::Euclidean ? 0.0 : (g == Geometry::Hyperbolic ? -1.0 : 1.0);
}

// (4.1.2) with a_i = ε_i e^{2u_i} and c = 4η e^{u_i+u_j}:
//   H²: cosh l = (c + (1+a_i)(1+a_j)) / ((1-a_i)(1-a_j))
//   S²: cos  l = (-c + (1-a_i)(1-a_j)) / ((1+a_i)(1+a_j))
// Both as w = cosh l - 1 (H²) or 1 - cos l (S²) = (c + 2(a_i + a_j)) / D with D the
// denominator, so that l = 2 asinh(√(w/2)) or 2 asin(√(w/2)) keeps every digit of a short edge:
// acosh / acos of a value rounded near 1 lose half of them (a relative error of about ε/l²:
// 5e-8 for l = 1e-4, measured; on 600-vertex lopsided disks enough noise to stall the curved
// disk-map routes near 1e-9). Differentiating, ∂a_i/∂u_i = 2a_i and ∂c/∂u_i = c.
EdgeLength edgeLength(Geometry g, double ui, double uj, double eta, int epsi, int epsj) {
  EdgeLength r;
  if (g == Geometry::Euclidean) {
    const double xi = std::exp(ui), xj = std::exp(uj);
    const double cross = eta * xi * xj;
    const double l2 = 2 * cross + epsi * xi * xi + epsj * xj * xj;
    if (!(l2 > 0) || !std::isfinite(l2)) return r;
    r.length = std::sqrt(l2);
    r.dLength_dui = (cross + epsi * xi * xi) / r.length;
    r.dLength_duj = (cross + epsj * xj * xj) / r.length;
    r.valid = true;
    return r;
  }
  const double ai = epsi * std::exp(2 * ui), aj = epsj * std::exp(2 * uj);
  const double c = 4 * eta * std::exp(ui + uj);
  const double sign = g == Geometry::Hyperbolic ? 1.0 : -1.0;  // H² vs S² pattern
  const double num = c + 2 * (ai + aj);
  const double den = (1 - sign * ai) * (1 - sign * aj);
  if (!(den > 0) || !std::isfinite(num)) return r;
  const double w = num / den;
  // w ∈ (0, ∞) in H², (0, 2) in S² (cos l ∈ (-1, 1)).
  if (!(w > 0) || (g == Geometry::Spherical && !(w < 2))) return r;
  const double dNum_dui = c + 4 * ai, dNum_duj = c + 4 * aj;
  const double dDen_dui = -2 * sign * ai * (1 - sign * aj);
  const double dDen_duj = -2 * sign * aj * (1 - sign * ai);
  const double dW_dui = (dNum_dui * den - num * dDen_dui) / (den * den);
  const double dW_duj = (dNum_duj * den - num * dDen_duj) / (den * den);
  const double half = std::sqrt(0.5 * w);  // sinh(l/2) or sin(l/2)
  const bool hyperbolic = g == Geometry::Hyperbolic;
  r.length = 2 * (hyperbolic ? std::asinh(half) : std::asin(half));
  const double s = hyperbolic ? std::sinh(r.length) : std::sin(r.length);  // dw = s dl
  r.dLength_dui = dW_dui / s;
  r.dLength_duj = dW_duj / s;
  r.valid = std::isfinite(r.dLength_dui) && std::isfinite(r.dLength_duj);
  return r;
}

double etaForLength(Geometry g, double length, double ui, double uj, int epsi, int epsj) {
  if (g == Geometry::Euclidean) {
    const double xi = std::exp(ui), xj = std::exp(uj);
    return (length * length - epsi * xi * xi - epsj * xj * xj) / (2 * xi * xj);
  }
  // The inverse of edgeLength's c = w·D − 2(a_i + a_j), w = 2 sinh²(l/2) or 2 sin²(l/2).
  const double ai = epsi * std::exp(2 * ui), aj = epsj * std::exp(2 * uj);
  const double sign = g == Geometry::Hyperbolic ? 1.0 : -1.0;
  const double half = g == Geometry::Hyperbolic ? std::sinh(0.5 * length) : std::sin(0.5 * length);
  const double w = 2 * half * half;
  return (w * (1 - sign * ai) * (1 - sign * aj) - 2 * (ai + aj)) / (4 * std::exp(ui + uj));
}

namespace {
// s(x) of Table B.1: the "sine" of the geometry.
double sineOf(Geometry g, double x) {
  return g == Geometry::Euclidean ? x : (g == Geometry::Hyperbolic ? std::sinh(x) : std::sin(x));
}
}  // namespace

bool cornerAngles(Geometry g, const std::array<double, 3>& l, std::array<double, 3>& angles) {
  for (int c = 0; c < 3; ++c) {
    const double a = l[c], b = l[(c + 1) % 3], d = l[(c + 2) % 3];
    if (!(a < b + d)) return false;  // also rejects NaN
  }
  if (g == Geometry::Spherical && !(l[0] + l[1] + l[2] < 2 * std::numbers::pi)) return false;
  if (g == Geometry::Euclidean) {
    for (int c = 0; c < 3; ++c) {
      const double li = l[c], lj = l[(c + 1) % 3], lk = l[(c + 2) % 3];
      const double cosTheta = (lj * lj + lk * lk - li * li) / (2 * lj * lk);
      // Valid triangles give |cos| ≤ 1 up to rounding; clamp only that rounding.
      angles[c] = std::acos(std::clamp(cosTheta, -1.0, 1.0));
    }
    return true;
  }
  // Half-angle formula, tan²(θ_i/2) = s(p - l_j) s(p - l_k) / (s(p) s(p - l_i)) with p the
  // half perimeter and s = sin or sinh: the cosine law's acos loses half the digits for
  // small angles (curvature stalled near 1e-8 on slivers of a lopsided disk, measured).
  // s(p - l_c) = s(½(l_{c+1} + l_{c+2} - l_c)) is shared by the three corners (sums commute
  // exactly), so 3 + 3 sines a triangle instead of 12 (the spherical route's flow spent a third
  // of its time in sin); p keeps each corner's own order of additions, so the angles are
  // bitwise those of the formula per corner.
  std::array<double, 3> opposite;  // s(p - l_c)
  for (int c = 0; c < 3; ++c)
    opposite[c] = sineOf(g, 0.5 * (l[(c + 1) % 3] + l[(c + 2) % 3] - l[c]));
  for (int c = 0; c < 3; ++c) {
    const int j = (c + 1) % 3, k = (c + 2) % 3;
    const double p = 0.5 * (l[c] + l[j] + l[k]);
    const double ratio = opposite[j] * opposite[k] / (sineOf(g, p) * opposite[c]);
    angles[c] = 2 * std::atan(std::sqrt(ratio));
  }
  return true;
}

// Derivative cosine law: with A = sinθ_i s(l_j) s(l_k) (the same for every corner by the sine
// law), ∂θ_i/∂l_i = s(l_i)/A and ∂θ_i/∂l_j = -s(l_i) cosθ_k / A. The sines and cosines are taken
// once per triangle (9 calls, not 18).
void angleLengthDerivatives(Geometry g, const std::array<double, 3>& l,
                            const std::array<double, 3>& angles,
                            std::array<std::array<double, 3>, 3>& d) {
  std::array<double, 3> sinAngle, cosAngle, sinLength;
  for (int i = 0; i < 3; ++i) {
    sinAngle[i] = std::sin(angles[i]);
    cosAngle[i] = std::cos(angles[i]);
    sinLength[i] = sineOf(g, l[i]);
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double A = sinAngle[i] * sinLength[j] * sinLength[k];
    const double si = sinLength[i];
    d[i][i] = si / A;
    d[i][j] = -si * cosAngle[k] / A;
    d[i][k] = -si * cosAngle[j] / A;
  }
}

}  // namespace confvis::conformal
