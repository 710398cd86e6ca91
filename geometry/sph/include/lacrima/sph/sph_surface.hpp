#pragma once
// The water surface of a particle liquid, for the renderer: particles -> a narrow-band level set
// (OpenVDB's ParticlesToLevelSet, spheres of radius 2 r: overlapping, so the liquid is one body)
// -> smoothed (a few iterations of mean-curvature flow, OpenVDB's LevelSetFilter) -> moved in by
// r, so that a flat face of the liquid lies where its outer particles end (centre + r) -> a
// closed, outward-facing triangle mesh (VolumeToMesh at the zero crossing, quads split) whose
// vertex normals are the level set's gradient there (smooth across the voxel-sized facets). Museth
// 2013, "VDB: High-Resolution Sparse Volumes with Dynamic Topology" (ACM TOG 32(3)), is OpenVDB's
// data structure; the dilate-smooth-erode sequence is the common practice for particle liquids
// (e.g. Zhu & Bridson 2005's union of spheres, smoothed).
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima::sph {

struct SurfaceParams {
  double voxelsPerRadius = 2.0;  // level-set resolution: voxel = r / voxelsPerRadius
  int smoothingIterations = 3;   // mean-curvature flow steps
};

// The surface of the liquid whose particles (radius `particleRadius`) are at `positions`; empty
// for no particles.
TriangleMesh surfaceOfParticles(const std::vector<Vec3d>& positions, double particleRadius,
                                const SurfaceParams& params = {});

}  // namespace lacrima::sph
