#pragma once
// The unified circle packing metric (Σ, γ, η, ε) of the dissertation's Chapter 4: six schemes
// times three background geometries, one formula family. Formulas were re-derived from (4.1.2)
// and the cosine law, not copied from Table B.1 (which has typos), and are verified against
// finite differences in circle_packing_test.cpp.
#include <array>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

enum class Geometry { Euclidean, Hyperbolic, Spherical };
enum class Scheme { Tangential, Thurston, InversiveDistance, Yamabe, VirtualRadius, Mixed };

const char* toString(Geometry g) noexcept;
const char* toString(Scheme s) noexcept;
Geometry parseGeometry(const std::string& name);  // euclidean | hyperbolic | spherical
Scheme parseScheme(const std::string& name);      // tangential | thurston | inversive | ...
constexpr std::array<Geometry, 3> kAllGeometries{Geometry::Euclidean, Geometry::Hyperbolic,
                                                 Geometry::Spherical};
constexpr std::array<Scheme, 6> kAllSchemes{Scheme::Tangential,    Scheme::Thurston,
                                            Scheme::InversiveDistance, Scheme::Yamabe,
                                            Scheme::VirtualRadius, Scheme::Mixed};

// Discrete conformal factor u from a circle radius γ (4.1.1), and back.
double conformalFactorFromRadius(Geometry g, double radius);
double radiusFromConformalFactor(Geometry g, double u);

// Edge length from (u_i, u_j, η_ij, ε_i, ε_j) by (4.1.2), with its partial derivatives.
// `valid` is false where the formula leaves the domain (e.g. cosh l < 1): the metric is invalid.
struct EdgeLength {
  double length = 0;
  double dLength_dui = 0;
  double dLength_duj = 0;
  bool valid = false;
};
EdgeLength edgeLength(Geometry g, double ui, double uj, double eta, int epsi, int epsj);

// The η that makes (4.1.2) give `length` at the given conformal factors (solves (4.1.2) for η).
double etaForLength(Geometry g, double length, double ui, double uj, int epsi, int epsj);

// A triangle's corner angles from its edge lengths (cosine law of the geometry). l[c] is the
// length of the edge opposite corner c. Returns false for lengths that violate the triangle
// inequality (or, on the sphere, a perimeter ≥ 2π).
bool cornerAngles(Geometry g, const std::array<double, 3>& l, std::array<double, 3>& angles);

// ∂θ_c/∂l_e for one triangle (derivative cosine law): d[c][e].
void angleLengthDerivatives(Geometry g, const std::array<double, 3>& l,
                            const std::array<double, 3>& angles,
                            std::array<std::array<double, 3>, 3>& d);

// Gauss-Bonnet for a triangle mesh with angle-deficit curvature: Σ K = 2πχ - κ·Area, where κ is
// the background curvature (0, -1, +1). Returns κ.
double backgroundCurvature(Geometry g) noexcept;

}  // namespace conformal
}  // namespace confvis
