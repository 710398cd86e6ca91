// Water seen from inside, with exact answers. In a uniform environment of radiance L, radiance
// inside a lossless dielectric of index n is n^2 L (the n^2 law of radiance, Veach 1997 §5.2;
// pbrt-v4 §9.5.2): the camera sees what a diver sees, not what an outside observer sees.
#include <gtest/gtest.h>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/materials/fresnel.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace water_analytic_test {

// Camera at the centre of a water ball: every camera ray meets the surface at normal
// incidence and is either transmitted (weight n^2 by the radiance scaling) or reflected straight
// back through the centre to the surface again; the sum is L_inside = T n^2 L + F L_inside, so
// L_inside = n^2 L. Checks the transmission's radiance scaling and the reflection bookkeeping.
TEST(WaterAnalytic, CameraInsideAWaterDropSeesNSquaredTimesTheEnvironment) {
  for (const float ior : {kTearIor, 1.8f}) {
    SCOPED_TRACE(ior);
    Frame frame;
    frame.materials.push_back(Material{"water", SmoothDielectricParams{ior, Color::Ones()}, Color::Zero()});
    frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
    frame.uniformBackground = Color::Ones();
    frame.camera = test::lookAt(Vec3::Zero(), Vec3(0.3f, 0.2f, -1.0f), 40.0f);
    frame.settings = test::smallSettings(16, 32, 200);
    const Film film = renderFrame(frame);
    test::expectMean(film, double(ior) * ior, 1e-3);
  }
}

// A box of water from y = -3 to 0 with a black floor inside at y = -2; the camera is under the
// surface at y = -1. Looking up inside Snell's window (30 degrees from the vertical), it sees
// the sky through the surface: T(30 deg) n^2 L, plus the reflected black floor. Beyond the
// critical angle (60 degrees; critical is 48.4 for n = 1.337) the surface is a perfect mirror of
// the black floor: exactly 0, no light may leak through.
Frame underwaterCamera(float degreesFromVertical) {
  Frame frame;
  frame.materials.push_back(Material{"water", SmoothDielectricParams{kTearIor, Color::Ones()}, Color::Zero()});
  frame.materials.push_back(Material{"black", DiffuseParams{Color::Zero()}, Color::Zero()});
  const float half = 50.0f;
  const Vec3 x(2 * half, 0, 0), y(0, 3, 0), z(0, 0, 2 * half);
  const Vec3 centre(0, -1.5f, 0);
  // Six faces with outward normals (edgeU x edgeV points out).
  struct Face {
    Vec3 centre, edgeU, edgeV;
  };
  const Face faces[] = {{centre + y / 2, z, x}, {centre - y / 2, x, z}, {centre + x / 2, y, z},
                        {centre - x / 2, z, y}, {centre + z / 2, x, y}, {centre - z / 2, y, x}};
  for (const Face& f : faces) frame.meshes.push_back(MeshInstance{makeRectangle(f.centre, f.edgeU, f.edgeV), 0});
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0, -2, 0), Vec3(0, 0, 90), Vec3(90, 0, 0)), 1});
  frame.uniformBackground = Color::Ones();
  const float angle = degreesToRadians(degreesFromVertical);
  const Vec3 eye(0, -1, 0);
  frame.camera = test::lookAt(eye, eye + Vec3(std::sin(angle), std::cos(angle), 0), 0.5f);
  frame.settings = test::smallSettings(8, 16, 50);
  return frame;
}

TEST(WaterAnalytic, UnderwaterTheSkyIsSeenInsideSnellsWindow) {
  const float cos30 = std::cos(degreesToRadians(30.0f));
  const double transmitted = (1.0 - fresnelDielectric(-cos30, kTearIor)) * kTearIor * kTearIor;
  test::expectMean(renderFrame(underwaterCamera(30.0f)), transmitted, 2e-3);
}

TEST(WaterAnalytic, UnderwaterBeyondTheCriticalAngleTheSurfaceIsAPerfectMirror) {
  const Film film = renderFrame(underwaterCamera(60.0f));
  for (size_t p = 0; p < film.rgba.size(); p += 4) ASSERT_EQ(film.rgba[p], 0.0f) << "pixel " << p / 4;
}

}  // namespace water_analytic_test
}  // namespace lacrima
