#pragma once
// Carrying liquid from one course of a flow path to the next when the surface moves (the path is
// traced again as the face moves, and the liquid on it must stay where it was on the skin). Both courses are FlowPaths on meshes of one topology
// (the skin posed at two frames): a point at arc length s of the old course is a material point of
// the surface (a triangle and barycentric weights); it is placed on the surface as it is now and
// projected to the nearest point of the new course, whose arc length is the image of s. A bead
// or film sitting on the skin therefore stays where it sat, up to the sideways step to the new
// course (the new course is the steepest-descent line through the moved surface; liquid off it is
// not modelled).
#include <mutex>
#include <unordered_map>
#include <vector>

#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/surface_flow.hpp"

namespace lacrima {

class FlowPathTransfer {
 public:
  // `from`: the old course (its points and arrivals, in the triangles of `skin`'s topology; its
  // arc lengths are the parameter s). `to`: the new course, its positions and arc lengths
  // measured on `skin` (the surface now). Throws InputError for a course with fewer than 2
  // points, or for a point whose triangle `skin` does not have.
  FlowPathTransfer(const FlowPath& from, const FlowPath& to, const TriangleMesh& skin);

  // The arc length on the new course of the material point at arc length s of the old one
  // (s clamped to the old course). Each s is projected once and remembered (a simulation replayed
  // from t = 0 for every frame asks the same arc lengths again: its trail cells' ends and its beads
  // at the change of course); thread-safe.
  double operator()(double s) const;
  // The distance (m, on the surface now) from that material point to its image on the new course.
  double sidewaysStep(double s) const;

 private:
  struct Piece {
    double s0 = 0.0, s1 = 0.0;
    Vec3d from = Vec3d::Zero(), to = Vec3d::Zero();
  };
  static std::vector<Piece> piecesOn(const FlowPath& path, const TriangleMesh& skin);
  Vec3d materialPoint(double s) const;
  double project(const Vec3d& p, double* distance) const;

  std::vector<Piece> old_;   // the old course's pieces placed on the surface now
  std::vector<Piece> new_;   // the new course's pieces
  mutable std::mutex mutex_;
  mutable std::unordered_map<double, double> images_;  // s -> its image, for the s asked so far
};

}  // namespace lacrima
