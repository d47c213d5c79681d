// Point location in a disk map (the bake's inverse of a piecewise-linear disk map): brute-force
// agreement inside, nearest boundary point outside, any hint.
#include <gtest/gtest.h>

#include <random>

#include "../src/disk_locator.hpp"
#include "bake_test_support.hpp"

namespace confvis {
namespace {

TEST(DiskLocator, FindsTheContainingTriangleFromAnyHintAndClampsOutsidePoints) {
  const SphereDiskMesh mesh = test::makeCapMesh(10, 1.2);
  const detail::DiskLocator locator(mesh.disk, mesh.triangles);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(-1.1, 1.1);
  std::uniform_int_distribution<int> anyTriangle(0, static_cast<int>(mesh.triangles.size()) - 1);
  int inside = 0, outside = 0;
  for (int i = 0; i < 4000; ++i) {
    const std::complex<double> z(uni(rng), uni(rng));
    int hint = i % 3 == 0 ? -1 : anyTriangle(rng);
    const detail::DiskLocator::Hit hit = locator.locate(z, hint);
    ASSERT_GE(hit.triangle, 0);
    EXPECT_EQ(hint, hit.triangle);
    const auto& t = mesh.triangles[hit.triangle];
    const std::complex<double> back = hit.barycentric[0] * mesh.disk[t[0]] +
                                      hit.barycentric[1] * mesh.disk[t[1]] +
                                      hit.barycentric[2] * mesh.disk[t[2]];
    for (double b : hit.barycentric) EXPECT_GE(b, 0.0);
    EXPECT_NEAR(hit.barycentric[0] + hit.barycentric[1] + hit.barycentric[2], 1.0, 1e-12);
    // Brute force: the distance from z to the polygon (0 inside).
    double distance = 1e9;
    for (const auto& tri : mesh.triangles) {
      const std::complex<double> a = mesh.disk[tri[0]], b = mesh.disk[tri[1]], c = mesh.disk[tri[2]];
      auto side = [](std::complex<double> p, std::complex<double> q, std::complex<double> r) {
        return ((q - p) * std::conj(r - p)).imag();  // > 0: r is right of p -> q
      };
      const double s0 = side(a, b, z), s1 = side(b, c, z), s2 = side(c, a, z);
      if ((s0 <= 0 && s1 <= 0 && s2 <= 0) || (s0 >= 0 && s1 >= 0 && s2 >= 0)) distance = 0;
      for (auto [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        const double s = std::clamp(((z - p) * std::conj(q - p)).real() / std::norm(q - p), 0.0, 1.0);
        distance = std::min(distance, std::abs(z - (p + s * (q - p))));
      }
    }
    if (distance == 0) {
      EXPECT_LT(std::abs(back - z), 1e-12) << z;  // inside: exact barycentric coordinates
      ++inside;
    } else {
      EXPECT_NEAR(std::abs(back - z), distance, 1e-12) << z;  // outside: the nearest point
      ++outside;
    }
  }
  EXPECT_GT(inside, 2000);
  EXPECT_GT(outside, 500);
}

}  // namespace
}  // namespace confvis
