#pragma once
// A face rig over a loaded glTF face: blendshapes, then head, jaw and eye-gaze joints.
// Bao et al. 2019, eq. 1: x(b, j) = T(j)(n + B b), evaluated per primitive.
#include <string>
#include <vector>

#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/rig/skinning.hpp"
#include "lacrima/mesh/sphere_fit.hpp"

namespace lacrima {

// One eyeball: the parts that rotate together with the gaze, and the part whose vertices are
// fitted with a sphere to find the centre of rotation. The sclera is the part to fit: it is
// close to a sphere, while the iris is a cap in front of it that would pull the fit forward.
struct EyeballSpec {
  std::string name;                // "left", "right" (for messages)
  std::string spherePart;          // GltfPrimitive::part fitted with a sphere, e.g. "M_ScleraLeft"
  std::vector<std::string> parts;  // GltfPrimitive::part values that rotate, e.g. sclera and iris
};

struct FaceRigConfig {
  Vec3 headPivot = Vec3::Zero();  // the head rotates about this point (roughly the top of the neck)
  Vec3 jawPivot = Vec3::Zero();   // the jaw rotates about this point (the hinge below the ears)
  // The blendshape whose per-vertex delta magnitude, normalised to 1 at its largest, is the jaw's
  // skinning weight. A face asset ships blendshapes but no skeleton; the jaw-open shape moves each
  // vertex about as much as the jaw bone carries it, so it is a weight field for free. It
  // underestimates near the hinge, where a jaw rotation moves vertices little anyway.
  std::string jawWeightTarget = "jawOpen";
  std::vector<EyeballSpec> eyes;
};

// A pose of the rig: blendshape weights b and joint parameters j.
struct FacePose {
  std::vector<float> blendshapeWeights;  // indexed like GltfAsset::targetNames; missing trailing = 0
  RigidJoint head;                       // about FaceRigConfig::headPivot, moves every primitive
  RigidJoint jaw;                        // about FaceRigConfig::jawPivot, weighted per vertex
  std::vector<Vec3> eyeEulerDegrees;     // one per FaceRigConfig::eyes (missing = 0): x pitch, y yaw
};

// The jaw hinge implied by a blendshape that opens the jaw: the rotation about an axis parallel
// to x (the face is symmetric about x = 0) that best explains the target's deltas.
struct JawHinge {
  Vec3 pivot = Vec3::Zero();
  float openingDegrees = 0.0f;  // rotation about +x that the blendshape at weight 1 corresponds to
};

// Fits the hinge to the vertices target k moves on one primitive (use a rigid part such as the
// lower teeth). Throws InputError when the target moves fewer than 3 vertices of the primitive or
// implies no rotation.
JawHinge estimateJawHinge(const GltfPrimitive& primitive, size_t target);

// Pivots and eyes for the ICT face (scenes/assets/ict-face): eyes are M_ScleraLeft + M_IrisLeft
// and M_ScleraRight + M_IrisRight, fitted on the scleras; the jaw pivot is estimateJawHinge on
// M_Teeth with jawOpen (the lower teeth move rigidly with the jaw); the head pivot is the bottom
// centre of M_Face's bounds (the neck), a stand-in for the atlas joint. Throws InputError when a
// needed part or target is missing.
FaceRigConfig ictFaceRigConfig(const GltfAsset& asset);

class FaceRig {
 public:
  // Copies the primitives, derives jaw weights and fits the eyeballs. Throws InputError for
  // unknown eye parts or an unknown jawWeightTarget (with the closest valid name).
  FaceRig(const GltfAsset& asset, FaceRigConfig config);

  // The posed primitives, in asset order. For zero weights and identity joints, bitwise the
  // neutral meshes; normals are recomputed (welded by weldMap) only for primitives that moved.
  // Throws InputError for non-finite weights or more weights/eyes than the rig has.
  std::vector<TriangleMesh> evaluate(const FacePose& pose) const;
  TriangleMesh evaluatePrimitive(size_t primitive, const FacePose& pose) const;

  size_t primitiveCount() const { return primitives_.size(); }
  const GltfPrimitive& primitive(size_t i) const { return primitives_[i]; }
  const std::vector<std::string>& targetNames() const { return targetNames_; }
  const FaceRigConfig& config() const { return config_; }
  // Jaw skinning weight per vertex of a primitive (empty when the jaw does not move it).
  const std::vector<float>& jawWeights(size_t primitive) const { return jawWeights_[primitive]; }
  // Fitted sphere of eye e (index into config().eyes).
  const FittedSphere& eyeball(size_t eye) const { return eyeballs_[eye]; }
  // Index into config().eyes of the eye a primitive belongs to, or -1.
  int eyeOfPrimitive(size_t primitive) const { return eyeOfPrimitive_[primitive]; }

 private:
  void validatePose(const FacePose& pose) const;
  bool skin(size_t primitive, const FacePose& pose, std::vector<Vec3>& positions) const;

  std::vector<GltfPrimitive> primitives_;
  std::vector<std::string> targetNames_;
  FaceRigConfig config_;
  std::vector<std::vector<float>> jawWeights_;
  std::vector<FittedSphere> eyeballs_;
  std::vector<int> eyeOfPrimitive_;
};

}  // namespace lacrima
