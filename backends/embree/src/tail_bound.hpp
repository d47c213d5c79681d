#pragma once
// TailLattice's check from the tail grid's statistics (tail_grid.hpp, TailGrid::smoothness),
// without the lattice's nodes (issue 23): an upper bound of what the per-node check measures,
// the lattice's second differences of the tails' direction D and offset O, over a whole tile.
//
// Along a lattice row (step h in q, wall pixels) F is a bilinear blend of its nodes, piecewise
// linear with kinks at the nodes (spacing s): |Delta_h F| <= h slope, and the second difference
// sums the slope's jumps (each at most |Delta_s^2 F| / s) under a tent of half-width h, at most
// h (h / s + 1) of them. D = F / |F| adds the normalisation's curvature (3 |Delta F|^2 / |F|^2).
// O = P_D M with M = a A + b B (a affine along x, b along y, tail_grid.hpp):
// Delta^2 (a A) = a Delta^2 A + Delta a (A(x + h) - A(x - h)), and the product rule for second
// differences with the projection P_D = I - D D^T. The offset's error is weighed by one over the
// least reach of the tile's cells, at least |e - c| (M scales with |e - c|); the rest of the bound
// comes from the grid's statistics, once per map.
#include "tail_grid.hpp"

namespace confvis::embree {

struct TileFrame {
  float step[2] = {0.0f, 0.0f};  // the lattice's step along x and y in q (wall pixels)
  float aMost = 0.0f, bMost = 0.0f;  // |a|, |b| over the tile
  float aStep = 0.0f, bStep = 0.0f;  // how much a changes a step along x, b along y
  // The least reach of the tile's cells (at least |e - c|; from the nodes' least h, tail_lattice.hpp).
  float reach = 0.0f;
};

// An upper bound of TailLattice's per-cell error estimate (the bilinear blend's angular error,
// (|D_xx| + |D_yy| + (|O_xx| + |O_yy|) / reach) / 8 from the second differences) of every cell
// whose nodes and their neighbours lie where `smoothness` was taken; infinity where F may vanish.
float tileBlendErrorBound(const TailGrid::Smoothness& smoothness, const TileFrame& frame);

}  // namespace confvis::embree
