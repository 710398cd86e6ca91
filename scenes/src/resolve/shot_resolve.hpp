#pragma once
// The resolving phase of loadShot (shot_loader.cpp), after binding (load/shot_binding.hpp): what the shot
// places on its assets' surfaces found on the assets posed at the shot's first frame, in the order
// each needs the others (flesh volumes on the skin as loaded; the skin refined under details and
// along liquid trails; then attachments, dripping tears and details, shedding and liquid tears,
// eyes, the flesh's skin and SPH colliders, on the refined skin).
#include "lacrima/scenes/shot_model.hpp"
#include "read/shot_checker.hpp"

namespace lacrima::shotfile {

// Resolves a shot read, loaded and bound without errors; each problem found goes to `checker` at its JSON pointer.
void resolveShot(Shot& shot, Checker& checker);

}  // namespace lacrima::shotfile
