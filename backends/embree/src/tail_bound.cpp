#include "tail_bound.hpp"

#include <algorithm>
#include <limits>

namespace confvis::embree {

namespace {

// Bounds of a bilinearly blended field's first and second differences along one axis at step h.
struct Differences {
  float first, second;
};

Differences differences(const TailGrid::FieldStats& field, int axis, float h, float spacing) {
  const float first = h * field.slope[axis];
  const float kinks = field.second[axis] / spacing * h * (h / spacing + 1.0f);
  return {first, std::min(2.0f * first, kinks)};
}

// The bound along one axis: D's second difference plus O's over |e - c|. `varying`: the
// moment whose coefficient changes along the axis (A along x, B along y), with its coefficient's
// largest size and change a step; `fixed` the other.
float axisBound(const TailGrid::Smoothness& s, int axis, float h, const TailGrid::FieldStats& varying,
                float coefficientMost, float coefficientStep, const TailGrid::FieldStats& fixed,
                float fixedMost, float reach) {
  const float least = s.f.least;
  const Differences f = differences(s.f, axis, h, s.fSpacing[axis]);
  const float turn = f.first / least;                                    // |Delta D|
  // N(g) = g / |g| along a straight piece: |N''| <= (1 + sqrt 5) / 2 |g'|^2 / |g|^2 (the turn's
  // tangential 2 sin cos plus its radial sin^2), so each one-sided remainder of N's first-order
  // expansion is at most half that times |Delta g|^2.
  const float turn2 = f.second / least + 1.6181f * turn * turn;  // |Delta^2 D|
  const Differences v = differences(varying, axis, h, s.momentSpacing[axis]);
  const Differences w = differences(fixed, axis, h, s.momentSpacing[axis]);
  const float m = coefficientMost * varying.most + fixedMost * fixed.most;  // |M|
  const float m1 = coefficientMost * v.first + coefficientStep * varying.most + fixedMost * w.first;
  const float m2 = coefficientMost * v.second + 2.0f * coefficientStep * v.first + fixedMost * w.second;
  // P = I - D D^T: |Delta P| <= 2 |Delta D| + |Delta D|^2, |Delta^2 P| <= 2 |Delta^2 D| + 2 |Delta D|^2.
  const float p1 = 2.0f * turn + turn * turn, p2 = 2.0f * turn2 + 2.0f * turn * turn;
  const float shift = m2 + m * p2 + 2.0f * p1 * m1;  // |Delta^2 O|
  return turn2 + shift / reach;
}

}  // namespace

float tileBlendErrorBound(const TailGrid::Smoothness& s, const TileFrame& frame) {
  if (!(s.f.least > 0.0f) || !(frame.reach > 0.0f))
    return std::numeric_limits<float>::infinity();
  const float alongX = axisBound(s, 0, frame.step[0], s.a, frame.aMost, frame.aStep, s.b,
                                 frame.bMost, frame.reach);
  const float alongY = axisBound(s, 1, frame.step[1], s.b, frame.bMost, frame.bStep, s.a,
                                 frame.aMost, frame.reach);
  // A relative margin for float rounding.
  return 1.001f * 0.125f * (alongX + alongY);
}

}  // namespace confvis::embree
