#pragma once
// How conformal a piecewise-linear map from a 3D mesh to the plane is: per face, the ratio of
// the Jacobian's singular values (1 = conformal), the log angle-ratio histogram of the
// dissertation's Fig. 4.5, flipped faces, and the roundness of the boundary.
#include <complex>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/mesh.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

struct DistortionStats {
  int faces = 0;
  double ratioMean = 0, ratioP50 = 0, ratioP99 = 0, ratioMax = 0;  // σ_max / σ_min per face
  int flippedFaces = 0;          // faces whose image is clockwise or collapsed
  int degenerateFaces = 0;       // faces of zero area in space, left out of the ratios
  double boundaryRoundness = 0;  // max | |uv| - 1 | over boundary vertices
  double logAngleRatioStd = 0;   // of log(mapped angle / input angle) over all corners
  double histogramMin = -0.5, histogramMax = 0.5;
  std::vector<int> logAngleRatioHistogram;  // equal bins over [min, max], outliers clamped
};

DistortionStats measureDistortion(const TriMesh& mesh, const std::vector<std::complex<double>>& uv,
                                  int histogramBins = 40);

nlohmann::json toJson(const DistortionStats& stats);

}  // namespace conformal
}  // namespace confvis
