#pragma once
// Internal: a starting conformal factor for the Euclidean disk map's flow (disk_map.cpp), and
// the flat metric's edge lengths.
#include <array>
#include <vector>

#include "confvis/base/vec3.hpp"
#include "confvis/conformal/intrinsic_triangulation.hpp"
#include "confvis/conformal/ricci_flow.hpp"

namespace confvis::conformal::detail {

// Edge lengths of a Euclidean metric by (4.1.2), l² = 2η·xᵢxⱼ + εᵢxᵢ² + εⱼxⱼ² with x = eᵘ, as
// edgeLength computes them (bit for bit) but with one exponential per vertex instead of two per
// edge (cave5 20 cm, both maps: 3.5M -> 0.6M instructions). False if an edge has no length.
bool euclideanEdgeLengths(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                          std::vector<double>& lengths);

// Adds to metric.u an estimate of the factor that flattens the annulus (the disk without the
// removed face or vertex star, whose remaining corners are `inner`) into a cylinder with straight
// boundaries, so that Newton starts near the answer: -log|p - c| around the hole's `centre` c
// (the removed face's centroid, or the removed vertex; log(z - c) is the planar annulus →
// cylinder map) plus, for each outer-boundary corner of angle α far from π, the factor of z^(π/α),
// (π/α - 1)·log|p - q|. Positions are the embedded `points`; `lengths` their edge lengths. Until
// every triangle is valid, a cone nearest to the invalid triangles is halved (up to 4 times),
// or where the log term is nearer, the whole guess (1, ½, ¼, ⅛, then none).
void addFlatteningGuess(const IntrinsicTriangulation& annulus, const std::vector<Vec3d>& points,
                        const std::vector<double>& lengths, const std::vector<int>& inner,
                        const Vec3d& centre, CirclePackingMetric& metric);

}  // namespace confvis::conformal::detail
