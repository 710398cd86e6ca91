// resolveShot; see shot_resolve.hpp.
#include "resolve/shot_resolve.hpp"

#include "resolve/detail_refinement.hpp"
#include "resolve/eye_resolve.hpp"
#include "resolve/flesh_resolve.hpp"
#include "resolve/liquid_tear_resolve.hpp"
#include "resolve/liquid_trail_refinement.hpp"
#include "resolve/shedding_tear_resolve.hpp"
#include "resolve/sph_resolve.hpp"
#include "resolve/surface_attachment.hpp"

namespace lacrima::shotfile {

void resolveShot(Shot& shot, Checker& checker) {
  // On the assets as loaded: the flesh volumes' boundaries are the skin's own tessellation.
  std::vector<FleshProblem> fleshProblems = resolveFleshVolumes(shot);
  // Before any surface point is found: they index the refined triangles.
  refineDetailRegions(shot);
  refineLiquidTrails(shot);
  resolveAttachments(shot);
  resolveTearsAndDetails(shot);
  // After the details' surface points, on the assets as they are now (possibly refined).
  for (const SheddingTearProblem& problem : resolveSheddingTears(shot))
    checker.error(problem.pointer, Anchor::Value, problem.message);
  for (const LiquidTearProblem& problem : resolveLiquidTears(shot))
    checker.error(problem.pointer, Anchor::Value, problem.message);
  for (const EyeProblem& problem : resolveEyes(shot)) checker.error(problem.pointer, Anchor::Value, problem.message);
  for (const FleshProblem& problem : fleshProblems) checker.error(problem.pointer, Anchor::Value, problem.message);
  embedFleshSkins(shot);
  for (const SphProblem& problem : resolveSphLiquids(shot)) checker.error(problem.pointer, Anchor::Value, problem.message);
}

}  // namespace lacrima::shotfile
