// Scenes with exact answers (Nori-style): they check the integrator, the light sampling and the
// MIS weights end to end. Tolerances are statistical: |mean - exact| < 5 standard errors
// (+ a float-rounding floor), so a biased estimator fails while noise does not.
#include <gtest/gtest.h>

#include "lacrima/renderer/environment.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace analytic_scenes_test {

using test::expectMean;
using test::lookAt;
using test::smallSettings;

// Nori's test: a camera inside a closed diffuse emitter of albedo a sees E / (1 - a).
Frame insideEmittingSphere(float albedo) {
  Frame frame;
  frame.materials.push_back(Material{"emitter", DiffuseParams{Color::Constant(albedo)}, Color::Ones()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
  frame.camera = lookAt(Vec3(0, 0, 0.2f), Vec3(0, 0, -1), 60.0f);
  frame.settings = smallSettings(16, 64, 1000);
  return frame;
}

TEST(AnalyticScenes, CameraInsideEmittingSphereSeesEmissionOverOneMinusAlbedo) {
  for (const auto& [albedo, exact] : {std::pair{0.5f, 2.0}, std::pair{0.8f, 5.0}}) {
    SCOPED_TRACE(albedo);
    const Film film = renderFrame(insideEmittingSphere(albedo));
    expectMean(film, exact, 1e-4);
  }
}

// Furnace: a smooth dielectric (water) sphere in a uniform environment of radiance 1 returns
// exactly the environment: Fresnel splits energy without loss, and every path escapes.
TEST(AnalyticScenes, WaterSphereInUniformEnvironmentReturnsTheEnvironment) {
  for (const float ior : {1.337f, 1.8f}) {
    SCOPED_TRACE(ior);
    Frame frame;
    frame.materials.push_back(Material{"water", SmoothDielectricParams{ior, Color::Ones()}, Color::Zero()});
    frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
    frame.uniformBackground = Color::Ones();
    frame.camera = lookAt(Vec3(0, 0, 4), Vec3::Zero(), 25.0f);  // the sphere fills most of the view
    frame.settings = smallSettings(24, 16, 200);
    const Film film = renderFrame(frame);
    expectMean(film, 1.0, 2e-4);
    // Stronger than the mean: no pixel may lose or gain energy.
    for (size_t p = 0; p < film.rgba.size(); p += 4) ASSERT_NEAR(film.rgba[p], 1.0f, 2e-3f) << "pixel " << p / 4;
  }
}

// A convex diffuse object under a uniform environment of radiance 1 reflects exactly its albedo.
// With an importance-sampled environment map this exercises NEE + MIS with the environment.
TEST(AnalyticScenes, DiffuseSphereUnderUniformEnvironmentMapReflectsItsAlbedo) {
  const float albedo = 0.6f;
  Frame frame;
  frame.materials.push_back(Material{"grey", DiffuseParams{Color::Constant(albedo)}, Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
  frame.environment = std::make_shared<EnvironmentMap>(8, 4, std::vector<float>(8 * 4 * 3, 1.0f), 1.0f, 0.0f);
  frame.camera = lookAt(Vec3(0, 0, 2.5f), Vec3::Zero(), 20.0f);  // every pixel sees the sphere
  frame.settings = smallSettings(16, 32, 20);
  const Film film = renderFrame(frame);
  expectMean(film, albedo, 1e-4);
}

// Form factor from a differential area to a parallel rectangle (a x b at height c) above one
// of its corners (Howell, "A Catalog of Radiation Heat Transfer Configuration Factors", B-3).
double cornerFormFactor(double a, double b, double c) {
  const double A = a / c, B = b / c;
  const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
  return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * M_PI);
}

// A Lambertian floor below a one-sided rectangle light: the floor's radiance under the light's
// centre is albedo * Le * F (F = form factor, four corner rectangles). Checks the rectangle
// light's sampling, its pdf in the MIS weights, and the BSDF-sampled hits of the light.
TEST(AnalyticScenes, FloorUnderRectangleLightMatchesFormFactor) {
  const float albedo = 0.5f, height = 1.0f, size = 1.0f;
  const Color radiance = Color::Constant(3.0f);
  Frame frame;
  frame.materials.push_back(Material{"floor", DiffuseParams{Color::Constant(albedo)}, Color::Zero()});
  frame.meshes.push_back(test::largeFloor(0));
  AreaLight light;
  light.center = Vec3(0, height, 0);
  light.edgeU = Vec3(size, 0, 0);
  light.edgeV = Vec3(0, 0, size);  // u x v = -y: emits downwards
  light.radiance = radiance;
  frame.lights.push_back(light);
  // Oblique camera with a tiny field of view: all pixels see the floor within ~1 mm of the centre.
  frame.camera = lookAt(Vec3(0, 0.5f, 2.0f), Vec3::Zero(), 0.05f);
  frame.settings = smallSettings(12, 64, 1);
  const double exact = albedo * radiance[0] * 4.0 * cornerFormFactor(size / 2, size / 2, height);
  const Film film = renderFrame(frame);
  expectMean(film, exact, 2e-3 * exact);  // the viewed patch is not a point: 0.2% floor
}

}  // namespace analytic_scenes_test
}  // namespace lacrima
