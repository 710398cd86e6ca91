// `lacrima check`: validate a shot file (and load its assets) without rendering.
#include <cstdio>

#include "commands.hpp"
#include "lacrima/scenes/shot.hpp"
#include "thread_cap.hpp"

namespace lacrima::cli {

int runCheck(const std::string& shotPath, int threads) {
  try {
    const Shot shot = withThreadCap(threads, [&] {
      Shot loaded = loadShot(shotPath);
      printShotWarnings(loaded);
      // Building the first frame also loads the environment map and checks the meshes.
      buildFrame(loaded, loaded.frameStart);
      return loaded;
    });
    std::printf("%s: OK (frames %d-%d at %g fps, %dx%d, %d spp)\n", shotPath.c_str(), shot.frameStart, shot.frameEnd,
                shot.fps, shot.render.width, shot.render.height, shot.render.samplesPerPixel);
    return kExitOk;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
