// The non-rigid fit of blendshape weights; see blendshape_fit.hpp.
#include "lacrima/tracking/blendshape_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lacrima/base/error.hpp"
#include "robust_cut.hpp"

namespace lacrima::tracking {

std::vector<Vec3d> BlendshapeModel::positions(const Eigen::VectorXd& weights) const {
  const Eigen::VectorXd offsets = deltas * weights;
  std::vector<Vec3d> out(neutral.positions.size());
  for (size_t v = 0; v < out.size(); ++v) out[v] = neutral.positions[v].cast<double>() + offsets.segment<3>(3 * long(v));
  return out;
}

TriangleMesh BlendshapeModel::shape(const Eigen::VectorXd& weights) const { return meshOf(positions(weights)); }

TriangleMesh BlendshapeModel::meshOf(const std::vector<Vec3d>& vertexPositions) const {
  TriangleMesh mesh = neutral;
  for (size_t v = 0; v < vertexPositions.size(); ++v) mesh.positions[v] = vertexPositions[v].cast<float>();
  computeSmoothNormals(mesh);
  return mesh;
}

BlendshapeModel blendshapeModelOf(const GltfAsset& asset, const std::string& part) {
  for (size_t index = 0; index < asset.primitives.size(); ++index) {
    const GltfPrimitive& primitive = asset.primitives[index];
    if (primitive.part != part) continue;
    BlendshapeModel model;
    model.neutral = primitive.mesh;
    model.targetNames = asset.targetNames;
    const long vertices = long(primitive.mesh.positions.size());
    model.deltas = Eigen::MatrixXd::Zero(3 * vertices, long(asset.targetNames.size()));
    for (size_t k = 0; k < primitive.targets.size() && k < asset.targetNames.size(); ++k) {
      const SparseDelta& target = primitive.targets[k];
      for (size_t j = 0; j < target.vertices.size(); ++j)
        model.deltas.block<3, 1>(3 * long(target.vertices[j]), long(k)) = target.deltas[j].cast<double>();
    }
    for (long k = 0; k < model.deltas.cols(); ++k) {
      double largest = 0.0;
      for (long v = 0; v < vertices; ++v) largest = std::max(largest, model.deltas.block<3, 1>(3 * v, k).norm());
      model.largestOffsets.push_back(largest);
    }
    model.landmarkVertices.assign(68, -1);
    for (const Landmark& l : asset.landmarks)
      if (l.primitive == int(index) && l.index >= 0 && l.index < 68) model.landmarkVertices[size_t(l.index)] = int(l.vertex);
    return model;
  }
  throw InputError(fmt::format("{}: no primitive '{}' to track", asset.path.string(), part));
}

namespace {

// Accumulates J^T J and J^T r of one residual row group.
struct NormalEquations {
  explicit NormalEquations(long m) : jtj(Eigen::MatrixXd::Zero(m, m)), jtr(Eigen::VectorXd::Zero(m)) {}
  void add(const Eigen::RowVectorXd& row, double residual) {
    jtj.selfadjointView<Eigen::Lower>().rankUpdate(row.transpose());
    jtr += row.transpose() * residual;
  }
  Eigen::MatrixXd jtj;
  Eigen::VectorXd jtr;
};

// The depth term's rows: per vertex facing the camera whose ray meets the measured surface within
// maxDistance, r = n . (p - q) / sigma and its row n^T R B_i / sigma. As in the rigid stage, pairs
// further apart than three times the median (at least 2 mm) are dropped: a lid's rim meeting the
// eyeball behind it, the jaw's edge meeting the neck.
double addDepthRows(const BlendshapeModel& model, const TriangleMesh& posedShape, const std::vector<Vec3d>& modelPositions,
                    const DepthFrame& frame, const Eigen::Isometry3d& pose, const BlendshapeFitParams& params,
                    NormalEquations& equations, int& pairs) {
  struct Pair {
    size_t vertex;
    Vec3d n;
    double residual, distance;
  };
  std::vector<Pair> candidates;
  const Eigen::Matrix3d rotation = pose.linear();
  for (size_t v = 0; v < modelPositions.size(); ++v) {
    const Vec3d p = pose * modelPositions[v];
    const Vec3d n = rotation * posedShape.normals[v].cast<double>();
    if (p.z() <= 0.0 || n.dot(p) >= 0.0) continue;
    const Eigen::Vector2d pixel = frame.camera().project(p);
    const auto q = frame.pointAt(pixel.x(), pixel.y());
    if (!q || (*q - p).norm() > params.maxDistance) continue;
    candidates.push_back({v, n, n.dot(p - *q), (*q - p).norm()});
  }
  pairs = 0;
  if (candidates.empty()) return 0.0;
  std::vector<double> distances;
  for (const Pair& c : candidates) distances.push_back(c.distance);
  const double cut = robustCut(std::move(distances), 0.002);
  double squared = 0.0;
  for (const Pair& c : candidates) {
    if (c.distance > cut) continue;
    const Eigen::RowVectorXd row =
        (c.n.transpose() * rotation) * model.deltas.middleRows<3>(3 * long(c.vertex)) / params.sigmaGeometry;
    equations.add(row, c.residual / params.sigmaGeometry);
    squared += c.residual * c.residual;
    ++pairs;
  }
  return pairs > 0 ? std::sqrt(squared / pairs) : 0.0;
}

// The landmark term's rows: two per seen landmark, r = (pi(p) - u) / sigma, rows dpi/dp R B_l / sigma.
double addLandmarkRows(const BlendshapeModel& model, const std::vector<Vec3d>& modelPositions,
                       const std::vector<Eigen::Vector2d>& landmarks, const PinholeCamera& camera,
                       const Eigen::Isometry3d& pose, const BlendshapeFitParams& params, NormalEquations& equations) {
  double squared = 0.0;
  int seen = 0;
  for (size_t l = 0; l < landmarks.size() && l < model.landmarkVertices.size(); ++l) {
    const int v = model.landmarkVertices[l];
    if (v < 0 || !landmarks[l].allFinite()) continue;
    const Vec3d p = pose * modelPositions[size_t(v)];
    const Eigen::Vector2d r = camera.project(p) - landmarks[l];
    Eigen::Matrix<double, 2, 3> projection;
    projection << camera.fx / p.z(), 0.0, -camera.fx * p.x() / (p.z() * p.z()), 0.0, camera.fy / p.z(),
        -camera.fy * p.y() / (p.z() * p.z());
    const Eigen::MatrixXd rows = projection * pose.linear() * model.deltas.middleRows<3>(3 * long(v)) / params.sigmaLandmark;
    equations.add(rows.row(0), r.x() / params.sigmaLandmark);
    equations.add(rows.row(1), r.y() / params.sigmaLandmark);
    squared += r.squaredNorm();
    ++seen;
  }
  return seen > 0 ? std::sqrt(squared / seen) : 0.0;
}

}  // namespace

BlendshapeFitResult fitBlendshapes(const BlendshapeModel& model, const DepthFrame& frame,
                                   const std::vector<Eigen::Vector2d>& landmarks, const Eigen::Isometry3d& pose,
                                   const Eigen::VectorXd& initial, const BlendshapeFitParams& params,
                                   const PriorTerm& prior) {
  const long m = model.targetCount();
  if (prior.prior && prior.prior->weightCount() != m)
    throw std::invalid_argument(fmt::format("fitBlendshapes: the prior has {} weights, the model {}", prior.prior->weightCount(), m));
  BlendshapeFitResult result;
  result.weights = initial.size() == m ? initial : Eigen::VectorXd::Zero(m);
  for (int iteration = 0; iteration < params.iterations; ++iteration) {
    const std::vector<Vec3d> positions = model.positions(result.weights);
    const TriangleMesh shape = model.meshOf(positions);
    NormalEquations equations(m);
    result.rmsDistance = addDepthRows(model, shape, positions, frame, pose, params, equations, result.pairs);
    result.rmsLandmarkPixels = addLandmarkRows(model, positions, landmarks, frame.camera(), pose, params, equations);
    Eigen::MatrixXd jtj = equations.jtj.selfadjointView<Eigen::Lower>();
    if (prior.prior) {
      // The normal equations are those of (1/2) sum r^2; Weise et al.'s energy is sum r^2 + E_prior,
      // so the prior enters at half its gradient and Hessian.
      Eigen::MatrixXd hessian;
      Eigen::VectorXd gradient;
      prior.prior->quadraticModel(result.weights, prior.previous, hessian, gradient);
      jtj += 0.5 * hessian;
      equations.jtr += 0.5 * gradient;
    }
    // The gradient is J^T r; a weight at a bound whose gradient pushes it out stays there, and so
    // does a target that barely moves this primitive (nothing to observe it by).
    std::vector<long> free;
    for (long k = 0; k < m; ++k) {
      const double w = result.weights[k], g = equations.jtr[k];
      if (!model.observable(k, params.minTargetMotion)) continue;
      if ((w <= 0.0 && g > 0.0) || (w >= 1.0 && g < 0.0)) continue;
      free.push_back(k);
    }
    if (free.empty()) break;
    Eigen::MatrixXd h(long(free.size()), long(free.size()));
    Eigen::VectorXd g(long(free.size()));
    for (size_t a = 0; a < free.size(); ++a) {
      g[long(a)] = equations.jtr[free[a]];
      for (size_t b = 0; b < free.size(); ++b) h(long(a), long(b)) = jtj(free[a], free[b]);
      h(long(a), long(a)) += params.damping * (1.0 + jtj(free[a], free[a]));
    }
    const Eigen::VectorXd step = h.ldlt().solve(-g);
    for (size_t a = 0; a < free.size(); ++a)
      result.weights[free[a]] = std::clamp(result.weights[free[a]] + step[long(a)], 0.0, 1.0);
  }
  return result;
}

}  // namespace lacrima::tracking
