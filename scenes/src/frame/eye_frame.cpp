// Eyes at a frame; see eye_frame.hpp.
#include "frame/eye_frame.hpp"

namespace lacrima::shotfile {

namespace {

void addMesh(TriangleMesh open, const TriangleMesh* close, uint32_t material, std::string name, Frame& frame) {
  open.name = std::move(name);
  MeshInstance instance(std::move(open), material);
  if (close && close->positions != instance.mesh.positions) {
    instance.positionsAtClose = close->positions;
    instance.normalsAtClose = close->normals;
  }
  frame.meshes.push_back(std::move(instance));
}

}  // namespace

void addEyes(const Shot& shot, const std::vector<std::vector<TriangleMesh>>& openAssets,
             const std::vector<std::vector<TriangleMesh>>* closeAssets, Frame& frame) {
  for (const ShotEye& eye : shot.eyes) {
    const std::vector<TriangleMesh>& open = openAssets[eye.asset];
    const std::vector<TriangleMesh>* close =
        closeAssets && !(*closeAssets)[eye.asset].empty() ? &(*closeAssets)[eye.asset] : nullptr;
    const std::string name = shot.assets[eye.asset].name + "/" + eye.part + "/";
    const EyeMeshes atOpen = buildEye(*eye.model, open[eye.primitive]);
    const std::optional<EyeMeshes> atClose =
        close ? std::optional<EyeMeshes>(buildEye(*eye.model, (*close)[eye.primitive])) : std::nullopt;
    addMesh(atOpen.cornea, atClose ? &atClose->cornea : nullptr, eye.corneaMaterial, name + "cornea", frame);
    addMesh(atOpen.sclera, atClose ? &atClose->sclera : nullptr, eye.scleraMaterial, name + "sclera", frame);
    addMesh(atOpen.iris, atClose ? &atClose->iris : nullptr, eye.irisMaterial, name + "iris", frame);
    addMesh(atOpen.pupil, atClose ? &atClose->pupil : nullptr, eye.pupilMaterial, name + "pupil", frame);
    if (!eye.lashes || eye.lashes->lashes.empty()) continue;
    const ShotLashes& lashes = *eye.lashes;
    const TriangleMesh lashesOpen = buildLashes(lashes.strips, lashes.lashes, open[lashes.primitive], lashes.params);
    const std::optional<TriangleMesh> lashesClose =
        close ? std::optional<TriangleMesh>(
                    buildLashes(lashes.strips, lashes.lashes, (*close)[lashes.primitive], lashes.params))
              : std::nullopt;
    addMesh(lashesOpen, lashesClose ? &*lashesClose : nullptr, lashes.materialId, name + "lashes", frame);
  }
}

}  // namespace lacrima::shotfile
