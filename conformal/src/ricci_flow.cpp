// The Newton loop of the unified Ricci flow (Appendix B, Algorithm 7), production version.
// The Hessian is assembled straight into a fixed, fill-reducing numbering of the unknowns
// (ricci_flow_newton.hpp). Factorisations are rare: after one, each Newton system is solved by
// conjugate gradients preconditioned with that frozen factor (inexact Newton with a forcing term
// that tightens as the error falls, so the convergence stays quadratic); only when CG would cost
// more than a fresh factorisation is the Hessian factorised again.
#include "confvis/conformal/ricci_flow.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include "confvis/base/error.hpp"
#include "metric_evaluation.hpp"
#include "ricci_flow_newton.hpp"

namespace confvis::conformal {
namespace {

using detail::MetricEvaluation;
using detail::SparseMatrix;
using Clock = std::chrono::steady_clock;

// Adds the lifetime of the scope to `total` (seconds).
class ScopedTimer {
 public:
  explicit ScopedTimer(double& total) : total_(total), start_(Clock::now()) {}
  ~ScopedTimer() { total_ += std::chrono::duration<double>(Clock::now() - start_).count(); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& total_;
  Clock::time_point start_;
};

double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// True if the target angle sum at some vertex (2π or π minus the target curvature) is out of
// reach of the triangles around it (each angle below π): only flips can help there.
bool needsMoreTriangles(const IntrinsicTriangulation& tri, const std::vector<double>& target) {
  std::vector<int> faces(tri.vertexCount, 0);
  for (const auto& fv : tri.faceVertices)
    for (int v : fv) ++faces[v];
  for (int v = 0; v < tri.vertexCount; ++v) {
    const double angleSum = (tri.vertexOnBoundary[v] ? 1 : 2) * std::numbers::pi - target[v];
    if (angleSum > faces[v] * std::numbers::pi - 1e-9) return true;
  }
  return false;
}

double residualNorm2(const std::vector<double>& target, const std::vector<double>& K) {
  double s = 0;
  for (std::size_t i = 0; i < K.size(); ++i) s += (target[i] - K[i]) * (target[i] - K[i]);
  return s;
}

std::string describeInvalid(const MetricEvaluation& eval) {
  return eval.invalidEdge >= 0 ? "edge " + std::to_string(eval.invalidEdge) + " has no length"
                               : "face " + std::to_string(eval.invalidFace) + " degenerates";
}

}  // namespace

RicciFlowReport runRicciFlow(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                             const std::vector<double>& target, const RicciFlowOptions& options) {
  checkTargetCurvature(tri, metric.geometry, target);
  RicciFlowReport report;
  auto& seconds = report.seconds;
  MetricEvaluation eval, trial;
  {
    ScopedTimer timer(seconds.evaluation);
    detail::evaluateMetric(tri, metric, metric.u, eval);
  }
  if (!eval.valid())
    throw Error(ErrorCode::InvalidInput, "initial metric is invalid: " + describeInvalid(eval));
  std::vector<double> weights;  // per edge, for the Delaunay test
  std::vector<char> lockedEdges;  // flipped to widen a fan: not to be flipped back
  auto flipToDelaunay = [&] {
    ScopedTimer timer(seconds.flips);
    const int flips = detail::restoreDelaunay(tri, metric, eval, weights, lockedEdges);
    report.flips += flips;
    return flips;
  };
  // Euclidean curvature is invariant under u → u + c: pin one vertex to remove the null space.
  const int pinned = metric.geometry == Geometry::Euclidean ? 0 : -1;
  bool flipping = options.delaunayFlips ||
                  (options.flipsWhenStuck && needsMoreTriangles(tri, target));
  bool started = false;  // inside the Newton loop
  auto startFlipping = [&] {
    flipping = true;
    if (report.flipsStartedAt < 0) report.flipsStartedAt = started ? report.iterations + 1 : 0;
    {
      ScopedTimer timer(seconds.flips);
      detail::edgeWeights(tri, eval, weights);
    }
    return flipToDelaunay();
  };
  if (flipping) {
    lockedEdges.assign(tri.edgeCount(), 0);
    ScopedTimer timer(seconds.flips);
    report.flips += detail::widenFans(tri, metric, eval, target, lockedEdges);
  }
  if (flipping) startFlipping();
  // Numbered after the initial flips: an ordering for the input's pattern can fill in ten
  // times more on the Delaunay one (measured); later flips renumber when the fill grows.
  std::optional<detail::NewtonSystem> system;
  double orderedFill = 0;  // nonzeros of L with the current numbering, before later flips
  auto orderUnknowns = [&] {
    system.emplace(tri, pinned);
    orderedFill = 0;
  };
  {
    ScopedTimer timer(seconds.analysis);
    orderUnknowns();
  }
  detail::PreorderedLDLT factor;
  bool analyzed = false, factored = false, patternStale = false;
  // CG steps allowed per Newton system before a fresh factorisation is cheaper.
  int cgBudget = 0;
  double cgRate = 0;  // residual reduction per CG step in the last solve
  auto assemble = [&] {
    if (patternStale) {  // same numbering; a fresh factor needs a new symbolic analysis
      system->invalidatePattern();
      patternStale = false;
      analyzed = false;
    }
    ScopedTimer timer(seconds.assembly);
    system->assemble(tri, eval, weights);
  };

  std::vector<double>& u = metric.u;
  std::vector<double> uTrial(u.size());
  Eigen::VectorXd rhs(system->size()), delta(system->size());
  double error = maxAbsDifference(target, eval.curvature);
  report.errorHistory.push_back(error);
  started = true;
  int degeneratedSteps = 0;  // Newton steps cut short by a degenerating triangle
  double lastStep = 1;       // fraction of the last Newton step taken
  while (error > options.tolerance) {
    if (report.iterations >= options.maxIterations) {
      std::ostringstream s;
      s << "Ricci flow did not converge in " << options.maxIterations
        << " iterations (max curvature error " << error << ", tolerance " << options.tolerance
        << ")";
      throw Error(ErrorCode::Unreachable, s.str());
    }
    assemble();
    if (flipping && flipToDelaunay() > 0) {
      patternStale = true;
      assemble();
    }
    auto setRightHandSide = [&] {
      for (int v = 0; v < tri.vertexCount; ++v)
        if (int i = system->unknownOf(v); i >= 0) rhs[i] = target[v] - eval.curvature[v];
    };
    setRightHandSide();

    bool solved = false;
    // Inexact Newton: relative residual min(0.1, error) keeps the convergence quadratic; no
    // tighter than needed for the linear residual to sit well below the flow's tolerance. After
    // a step cut below a quarter, ten times tighter: a rough direction can keep running into the
    // same degenerating triangle (an inversive-distance flow crawled at error 1.2 that way).
    const double cgTolerance =
        std::min(0.1, std::max(error, 0.1 * options.tolerance / rhs.norm())) *
        (lastStep < 0.25 ? 0.1 : 1.0);
    // The last solve's convergence rate predicts this one's cost: refactorise straight away
    // when CG would not make it within budget.
    if (factored && cgRate < 1 && std::log(cgTolerance) / std::log(cgRate) > cgBudget)
      factored = false;
    if (factored) {
      ScopedTimer timer(seconds.solve);
      const auto cg =
          detail::preconditionedCg(*system, factor, rhs, cgTolerance, cgBudget, delta);
      report.cgIterations += cg.iterations;
      cgRate = cg.iterations > 0 ? std::pow(cg.reduction, 1.0 / cg.iterations) : 0;
      solved = cg.converged;
    }
    if (!solved) {
      const SparseMatrix* H;
      {
        ScopedTimer timer(seconds.assembly);
        H = &system->upper(tri);
      }
      if (!analyzed) {
        ScopedTimer timer(seconds.analysis);
        factor.analyze(*H);
        ++report.symbolicAnalyses;
        // After flips the old numbering may fill in far more (10x, measured, for an ordering
        // made before the initial Delaunay flips): then number the unknowns afresh.
        if (orderedFill > 0 && factor.factorNonZeros() > 1.2 * orderedFill) {
          orderUnknowns();
          assemble();
          setRightHandSide();
          H = &system->upper(tri);
          factor.analyze(*H);
          ++report.symbolicAnalyses;
          orderedFill = 0;
        }
        if (orderedFill == 0) orderedFill = factor.factorNonZeros();
        analyzed = true;
        const double cgStepFlops = factor.solveFlops() + 4.0 * H->nonZeros();
        cgBudget = std::clamp(static_cast<int>(0.5 * factor.factorizationFlops() / cgStepFlops),
                              4, 200);
      }
      {
        ScopedTimer timer(seconds.factorization);
        factor.factorizeValues(*H);
        ++report.factorizations;
        cgRate = 0;
        factor.preparePreconditioner();
      }
      ScopedTimer timer(seconds.solve);
      factored = factor.info() == Eigen::Success;
      if (factored) {
        delta = factor.solve(rhs);
        factored = delta.allFinite();
      }
      // Without a usable Newton step (the spherical energy is not convex) fall back to the flow
      // direction du = K̄ - K itself.
      if (!factored) delta = rhs;
    }

    // Backtracking: a step must keep every triangle valid and reduce |K̄ - K|². With flips, a
    // step cut short because a triangle would degenerate is taken, the triangulation made
    // Delaunay there, and the rest of the Newton step tried from that point.
    double reference = residualNorm2(target, eval.curvature);
    double remaining = 1.0, alpha = 1.0;
    bool accepted = false, degenerated = false;
    int stage = 0;
    for (int halving = 0; halving < 60; ++halving) {
      {
        ScopedTimer timer(seconds.evaluation);
        for (int v = 0; v < tri.vertexCount; ++v) {
          const int i = system->unknownOf(v);
          uTrial[v] = i >= 0 ? u[v] + alpha * delta[i] : u[v];
        }
        detail::evaluateMetric(tri, metric, uTrial, trial);
      }
      const double r = trial.valid() ? residualNorm2(target, trial.curvature) : 0;
      if (trial.valid() && r < (1 - 1e-4 * alpha / remaining) * reference) {
        accepted = true;
        u.swap(uTrial);
        std::swap(eval, trial);
        remaining -= alpha;
        if (!degenerated || ++stage == 8 || remaining < 1e-3) break;
        // Flips come on mid-flow only for a step cut to under a quarter, or for the third step
        // in a row cut short: a mild cut is cheaper to live with than re-ordering and
        // re-factorising a re-triangulated system.
        if (stage == 1) ++degeneratedSteps;
        if (!flipping && (!options.flipsWhenStuck || (alpha >= 0.25 && degeneratedSteps < 3)))
          break;
        if (startFlipping() == 0) break;
        patternStale = true;
        reference = residualNorm2(target, eval.curvature);
        alpha = remaining;
        degenerated = false;
        continue;
      }
      // Past the first stage only the whole rest of the step is tried, and once more up to where
      // a triangle would degenerate; no halving: a new Newton direction is cheaper than
      // backtracking along an old one (100k: 9 -> 7 Newton steps, 48 -> 38 CG steps).
      if (stage > 0 && (trial.valid() || degenerated)) break;
      ++report.stepHalvings;
      if (!trial.valid() && !degenerated) {
        // Go most of the way to where the first triangle degenerates (flips there may remove
        // it), rather than halving blindly.
        degenerated = true;
        const double fraction = detail::degenerationStep(tri, eval, trial);
        if (fraction > 0.05) {
          alpha *= 0.9 * fraction;
          continue;
        }
      }
      alpha *= 0.5;
    }
    if (!accepted && !flipping && options.flipsWhenStuck) {
      if (startFlipping() > 0) {
        patternStale = true;
        continue;  // a new Newton step on the flipped triangulation
      }
    }
    if (!accepted) {
      std::ostringstream s;
      s << "Ricci flow stalled at max curvature error " << error << " after " << report.iterations
        << " iterations: no step keeps every triangle valid ("
        << (trial.valid() ? "error would grow" : describeInvalid(trial)) << ")";
      if (!flipping) s << "; enabling Delaunay edge flips may help";
      s << ", or the target curvature is not reachable for this mesh";
      throw Error(ErrorCode::Unreachable, s.str());
    }
    lastStep = 1 - remaining;
    ++report.iterations;
    error = maxAbsDifference(target, eval.curvature);
    report.errorHistory.push_back(error);
    if (options.onIteration) options.onIteration(report.iterations, error);
  }
  for (double x : metric.u)
    if (!std::isfinite(x)) throw Error(ErrorCode::Internal, "Ricci flow produced a non-finite factor");
  report.maxCurvatureError = error;
  return report;
}

}  // namespace confvis::conformal
