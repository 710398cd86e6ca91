#pragma once
// A synthetic depth sensor, for validating the tracker on a performance whose answer is known:
// triangles rasterised to a depth map (z-buffer, the depth of the nearest surface at each pixel
// centre), then the noise of a structured-light sensor added.
#include <cstdint>

#include "lacrima/mesh/mesh.hpp"
#include "lacrima/tracking/depth_frame.hpp"

namespace lacrima::tracking {

// The depth of `cameraSpaceMesh` (camera-space positions, z > 0 in front) at every pixel centre
// its triangles cover; the nearest wins. Triangles crossing z <= `nearPlane` are skipped.
DepthFrame rasterizeDepth(const TriangleMesh& cameraSpaceMesh, const PinholeCamera& camera, double nearPlane = 0.05);

// The axial noise of a Kinect v1 (Nguyen, Izadi & Lovell 2012, their axial model, for surfaces within 60
// degrees of facing the sensor): sigma_z(z) = 0.0012 + 0.0019 (z - 0.4)^2 metres, scaled by
// `scale` (0: none).
double kinectAxialNoise(double depth, double scale = 1.0);

// Adds Gaussian noise of standard deviation kinectAxialNoise(z, scale) to every measured depth;
// the same (seed, pixel) always draws the same number, so a frame is reproducible.
void addSensorNoise(DepthFrame& frame, double scale, uint64_t seed);

}  // namespace lacrima::tracking
