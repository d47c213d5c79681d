// The Newton loop of the unified Ricci flow (Appendix B, Algorithm 7), production version.
// The Hessian is assembled straight into a fixed, fill-reducing numbering of the unknowns
// (ricci_flow_newton.hpp). Factorisations are rare: after one, each Newton system is solved by
// conjugate gradients preconditioned with that frozen factor (inexact Newton with a forcing term
// that tightens as the error falls, so the convergence stays quadratic); only when CG would cost
// more than a fresh factorisation is the Hessian factorised again.
#include "confvis/conformal/ricci_flow.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#include "metric_evaluation.hpp"
#include "ricci_flow_newton.hpp"

namespace confvis::conformal {
namespace {

using detail::MetricEvaluation;
using detail::SparseMatrix;

// Adds the lifetime of the scope to `total` (seconds).
class ScopedTimer {
 public:
  explicit ScopedTimer(double& total) : total_(total), start_(SteadyClock::now()) {}
  ~ScopedTimer() { total_ += secondsSince(start_); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& total_;
  SteadyClock::time_point start_;
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

// One run of the flow: the Newton loop's state and its steps.
class NewtonFlow {
 public:
  NewtonFlow(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
             const std::vector<double>& target, const RicciFlowOptions& options)
      : tri_(tri), metric_(metric), target_(target), options_(options) {}

  RicciFlowReport run();

 private:
  void prepare();                     // initial evaluation, flips and numbering
  void orderUnknowns();               // AMD numbering of the current triangulation
  int startFlipping();                // flips on from here: Delaunay restored now
  int flipToDelaunay();
  void assemble();
  void setRightHandSide();
  void solveNewtonSystem();           // delta_ from the frozen factor (CG) or a fresh one
  void factorise();
  bool lineSearch(double& stepTaken);  // false if no step is acceptable
  [[noreturn]] void stall() const;

  IntrinsicTriangulation& tri_;
  CirclePackingMetric& metric_;
  std::vector<double> target_;      // a copy: options_.updateTarget may change it
  const RicciFlowOptions& options_;
  RicciFlowReport report_;
  RicciFlowReport::Seconds& seconds_ = report_.seconds;

  MetricEvaluation eval_, trial_;
  double error_ = 0;
  std::vector<double> weights_;      // per edge, for the Delaunay test
  std::vector<char> lockedEdges_;    // flipped to widen a fan: not to be flipped back
  bool flipping_ = false;
  bool started_ = false;             // inside the Newton loop

  std::optional<detail::NewtonSystem> system_;
  detail::PreorderedLDLT factor_;
  double orderedFill_ = 0;           // nonzeros of L with the current numbering, before flips
  bool analyzed_ = false, factored_ = false, patternStale_ = false;
  int cgBudget_ = 0;                 // CG steps per system before a factorisation is cheaper
  double cgRate_ = 0;                // residual reduction per CG step in the last solve
  Eigen::VectorXd rhs_, delta_;
  std::vector<double> uTrial_;
  double lastStep_ = 1;              // fraction of the last Newton step taken
  int degeneratedSteps_ = 0;         // Newton steps cut short by a degenerating triangle
};

RicciFlowReport NewtonFlow::run() {
  prepare();
  started_ = true;
  while (error_ > options_.tolerance) {
    if (report_.iterations >= options_.maxIterations) {
      std::ostringstream s;
      s << "Ricci flow did not converge in " << options_.maxIterations
        << " iterations (max curvature error " << error_ << ", tolerance "
        << options_.tolerance << ")";
      throw Error(ErrorCode::Unreachable, s.str());
    }
    assemble();
    if (flipping_ && flipToDelaunay() > 0) {
      patternStale_ = true;
      assemble();
    }
    setRightHandSide();
    solveNewtonSystem();
    double stepTaken = 0;
    if (!lineSearch(stepTaken)) {
      if (flipping_ || !options_.flipsWhenStuck || startFlipping() == 0) stall();
      patternStale_ = true;
      continue;  // a new Newton step on the flipped triangulation
    }
    lastStep_ = stepTaken;
    ++report_.iterations;
    if (options_.updateTarget && options_.updateTarget(tri_, metric_, eval_.curvature, target_))
      ++report_.targetUpdates;
    error_ = maxAbsDifference(target_, eval_.curvature);
    report_.errorHistory.push_back(error_);
    if (options_.onIteration) options_.onIteration(report_.iterations, error_);
  }
  for (double x : metric_.u)
    if (!std::isfinite(x))
      throw Error(ErrorCode::Internal, "Ricci flow produced a non-finite factor");
  report_.maxCurvatureError = error_;
  return report_;
}

void NewtonFlow::prepare() {
  checkTargetCurvature(tri_, metric_.geometry, target_);
  {
    ScopedTimer timer(seconds_.evaluation);
    detail::evaluateMetric(tri_, metric_, metric_.u, eval_);
    ++report_.evaluations;
  }
  if (!eval_.valid())
    throw Error(ErrorCode::InvalidInput, "initial metric is invalid: " + describeInvalid(eval_));
  if (options_.delaunayFlips || (options_.flipsWhenStuck && needsMoreTriangles(tri_, target_))) {
    lockedEdges_.assign(tri_.edgeCount(), 0);
    {
      ScopedTimer timer(seconds_.flips);
      report_.flips += detail::widenFans(tri_, metric_, eval_, target_, lockedEdges_);
    }
    startFlipping();
  }
  // Numbered after the initial flips: an ordering for the input's pattern can fill in ten
  // times more on the Delaunay one (measured); later flips renumber when the fill grows.
  {
    ScopedTimer timer(seconds_.analysis);
    orderUnknowns();
  }
  rhs_.resize(system_->size());
  delta_.resize(system_->size());
  uTrial_.resize(metric_.u.size());
  error_ = maxAbsDifference(target_, eval_.curvature);
  report_.errorHistory.push_back(error_);
}

void NewtonFlow::orderUnknowns() {
  // Euclidean curvature is invariant under u → u + c: pin one vertex to remove the null space.
  system_.emplace(tri_, metric_.geometry == Geometry::Euclidean ? 0 : -1);
  orderedFill_ = 0;
}

int NewtonFlow::startFlipping() {
  flipping_ = true;
  if (report_.flipsStartedAt < 0) report_.flipsStartedAt = started_ ? report_.iterations + 1 : 0;
  {
    ScopedTimer timer(seconds_.flips);
    detail::edgeWeights(tri_, eval_, weights_);
  }
  return flipToDelaunay();
}

int NewtonFlow::flipToDelaunay() {
  ScopedTimer timer(seconds_.flips);
  const int flips = detail::restoreDelaunay(tri_, metric_, eval_, weights_, lockedEdges_);
  report_.flips += flips;
  return flips;
}

void NewtonFlow::assemble() {
  if (patternStale_) {  // same numbering; a fresh factor needs a new symbolic analysis
    system_->invalidatePattern();
    patternStale_ = false;
    analyzed_ = false;
  }
  ScopedTimer timer(seconds_.assembly);
  system_->assemble(tri_, eval_, weights_);
}

void NewtonFlow::setRightHandSide() {
  for (int v = 0; v < tri_.vertexCount; ++v)
    if (int i = system_->unknownOf(v); i >= 0) rhs_[i] = target_[v] - eval_.curvature[v];
}

void NewtonFlow::solveNewtonSystem() {
  // Inexact Newton: relative residual min(0.1, error) keeps the convergence quadratic; no
  // tighter than needed for the linear residual to sit well below the flow's tolerance. After
  // a step cut below a quarter, ten times tighter: a rough direction can keep running into the
  // same degenerating triangle (an inversive-distance flow crawled at error 1.2 that way).
  const double cgTolerance =
      std::min(0.1, std::max(error_, 0.1 * options_.tolerance / rhs_.norm())) *
      (lastStep_ < 0.25 ? 0.1 : 1.0);
  // The last solve's convergence rate predicts this one's cost: refactorise straight away
  // when CG would not make it within budget.
  if (factored_ && cgRate_ < 1 && std::log(cgTolerance) / std::log(cgRate_) > cgBudget_)
    factored_ = false;
  if (factored_) {
    ScopedTimer timer(seconds_.solve);
    const auto cg =
        detail::preconditionedCg(*system_, factor_, rhs_, cgTolerance, cgBudget_, delta_);
    report_.cgIterations += cg.iterations;
    cgRate_ = cg.iterations > 0 ? std::pow(cg.reduction, 1.0 / cg.iterations) : 0;
    if (cg.converged) return;
  }
  factorise();
  ScopedTimer timer(seconds_.solve);
  factored_ = factor_.info() == Eigen::Success;
  if (factored_) {
    // With a fresh factor, CG preconditioned by its single-precision copy meets the tolerance
    // in one to three steps, cheaper than Eigen's double-precision triangular solves; those
    // remain for a factor CG cannot use (an indefinite spherical Hessian).
    const auto cg = detail::preconditionedCg(*system_, factor_, rhs_, cgTolerance, 4, delta_);
    report_.cgIterations += cg.iterations;
    if (cg.converged) return;
    delta_ = factor_.solve(rhs_);
    factored_ = delta_.allFinite();
  }
  // Without a usable Newton step (the spherical energy is not convex) fall back to the flow
  // direction du = K̄ - K itself.
  if (!factored_) delta_ = rhs_;
}

void NewtonFlow::factorise() {
  const SparseMatrix* H;
  {
    ScopedTimer timer(seconds_.assembly);
    H = &system_->upper(tri_);
  }
  if (!analyzed_) {
    ScopedTimer timer(seconds_.analysis);
    factor_.analyze(*H);
    ++report_.symbolicAnalyses;
    // After flips the old numbering may fill in far more (10x, measured, for an ordering made
    // before the initial Delaunay flips): then number the unknowns afresh.
    if (orderedFill_ > 0 && factor_.factorNonZeros() > 1.2 * orderedFill_) {
      orderUnknowns();
      assemble();
      setRightHandSide();
      H = &system_->upper(tri_);
      factor_.analyze(*H);
      ++report_.symbolicAnalyses;
    }
    if (orderedFill_ == 0) orderedFill_ = factor_.factorNonZeros();
    analyzed_ = true;
    const double cgStepFlops = factor_.solveFlops() + 4.0 * H->nonZeros();
    // At least 6: under ~5k unknowns a factorisation costs more than its flops say (`upper` and
    // the preconditioner set-up); cave5 20 cm disk maps: 2 -> 1 factorisation each, 188.2M ->
    // 182.0M instructions. From 10 cm up the flop ratio is above 6 and decides alone.
    cgBudget_ =
        std::clamp(static_cast<int>(0.5 * factor_.factorizationFlops() / cgStepFlops), 6, 200);
  }
  ScopedTimer timer(seconds_.factorization);
  factor_.factorizeValues(*H);
  ++report_.factorizations;
  cgRate_ = 0;
  factor_.preparePreconditioner();
}

// Backtracking: a step must keep every triangle valid and reduce |K̄ - K|². With flips, a step
// cut short because a triangle would degenerate is taken, the triangulation made Delaunay
// there, and the rest of the Newton step tried from that point ("stages").
bool NewtonFlow::lineSearch(double& stepTaken) {
  std::vector<double>& u = metric_.u;
  double reference = residualNorm2(target_, eval_.curvature);
  double remaining = 1.0, alpha = 1.0;
  bool accepted = false, degenerated = false;
  int stage = 0;
  for (int halving = 0; halving < 60; ++halving) {
    {
      ScopedTimer timer(seconds_.evaluation);
      for (int v = 0; v < tri_.vertexCount; ++v) {
        const int i = system_->unknownOf(v);
        uTrial_[v] = i >= 0 ? u[v] + alpha * delta_[i] : u[v];
      }
      detail::evaluateMetric(tri_, metric_, uTrial_, trial_);
      ++report_.evaluations;
    }
    if (trial_.valid() &&
        residualNorm2(target_, trial_.curvature) < (1 - 1e-4 * alpha / remaining) * reference) {
      accepted = true;
      u.swap(uTrial_);
      std::swap(eval_, trial_);
      remaining -= alpha;
      if (!degenerated || ++stage == 8 || remaining < 1e-3) break;
      // Flips come on mid-flow only for a step cut to under a quarter, or for the third step in
      // a row cut short: a mild cut is cheaper to live with than re-ordering and
      // re-factorising a re-triangulated system.
      if (stage == 1) ++degeneratedSteps_;
      if (!flipping_ && (!options_.flipsWhenStuck || (alpha >= 0.25 && degeneratedSteps_ < 3)))
        break;
      if (startFlipping() == 0) break;
      patternStale_ = true;
      reference = residualNorm2(target_, eval_.curvature);
      alpha = remaining;
      degenerated = false;
      continue;
    }
    // Past the first stage only the whole rest of the step is tried, and once more up to where
    // a triangle would degenerate; no halving: a new Newton direction is cheaper than
    // backtracking along an old one (100k: 9 -> 7 Newton steps, 48 -> 38 CG steps).
    if (stage > 0 && (trial_.valid() || degenerated)) break;
    ++report_.stepHalvings;
    if (!trial_.valid() && !degenerated) {
      // Go most of the way to where the first triangle degenerates (flips there may remove
      // it), rather than halving blindly.
      degenerated = true;
      const double fraction = detail::degenerationStep(tri_, metric_, u, uTrial_, eval_, trial_);
      if (fraction > 0.05) {
        alpha *= 0.9 * fraction;
        continue;
      }
      if (stage > 0) break;  // a later stage that gains under 5% is not worth halvings
    }
    alpha *= 0.5;
  }
  stepTaken = 1 - remaining;
  return accepted;
}

void NewtonFlow::stall() const {
  std::ostringstream s;
  s << "Ricci flow stalled at max curvature error " << error_ << " after "
    << report_.iterations << " iterations: no step keeps every triangle valid ("
    << (trial_.valid() ? "error would grow" : describeInvalid(trial_)) << ")";
  if (!flipping_) s << "; enabling Delaunay edge flips may help";
  s << ", or the target curvature is not reachable for this mesh";
  throw Error(ErrorCode::Unreachable, s.str());
}

}  // namespace

RicciFlowReport runRicciFlow(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                             const std::vector<double>& target, const RicciFlowOptions& options) {
  return NewtonFlow(tri, metric, target, options).run();
}

}  // namespace confvis::conformal
