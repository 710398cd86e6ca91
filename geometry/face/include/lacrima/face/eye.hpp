#pragma once
// An eye for close-ups built from an eyeball shell mesh (the ICT face's M_Sclera*: a sphere with a
// corneal bulge): the shell is cut at the limbus into an opaque sclera and a clear cornea cap; the
// cap is closed by a wall and a flat back inside the ball so it bounds the anterior chamber (one dielectric
// volume, cornea and aqueous humour merged), and an iris with depth (a cone from the limbus to the
// pupil margin, set back behind the corneal apex) and a pupil sit inside that chamber.
// Analysed once on the rest shell (analyseEye), then built on every posed shell (buildEye): the
// cap and sclera are the posed shell's own triangles, split where the limbus circle crosses them
// (so the limbus is the circle, not a zig-zag along the shell's edges), the rest follows the
// shell's rigid motion.
#include <cstdint>
#include <string>
#include <vector>

#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

struct EyeParams {
  float limbusRadius = 5.9e-3f;  // metres from the optical axis (human corneal diameter ~11.8 mm)
  float pupilRadius = 2.0e-3f;   // metres
  float irisDepth = 2.6e-3f;     // pupil margin behind the corneal apex, metres (about the limbus plane)
  int irisRings = 6, irisSegments = 64;
};

// A vertex added where the limbus crosses an edge of the shell: (1 - t) a + t b of shell vertices.
struct LimbusCrossing {
  uint32_t a = 0, b = 0;
  float t = 0.0f;
};

// What analyseEye finds on the rest shell.
struct EyeModel {
  EyeParams params;
  Vec3 center = Vec3::Zero();     // fitted eyeball centre (rest)
  float radius = 0.0f;            // fitted eyeball radius (the shell without the bulge)
  Vec3 axis = Vec3::UnitZ();      // optical axis, unit, centre -> corneal apex
  Vec3 up = Vec3::UnitY();        // unit, perpendicular to axis (world +Y projected)
  float apexHeight = 0.0f;        // corneal apex along the axis from the centre
  // The shell cut at the limbus: its vertices, then one per crossed edge (crossings); its
  // triangles, those crossed split in three (cutIndices, three per triangle).
  std::vector<LimbusCrossing> crossings;
  std::vector<uint32_t> cutIndices;
  std::vector<uint32_t> weldMap;  // findCoincidentVertices of the cut rest shell
  std::vector<uint32_t> corneaTriangles, scleraTriangles;  // partition of the cut shell's triangles
  std::vector<uint32_t> limbusLoop;  // welded vertex indices of the cap's boundary, in cap winding order
  std::vector<Vec2> irisRoot;  // per iris segment (equal angles from `right` towards `up`): (radius, height)
  float irisRootRadius = 0.0f, irisRootHeight = 0.0f;  // the root's largest radius and lowest height
  float pupilHeight = 0.0f;                             // pupil margin along the axis (local)
  float backHeight = 0.0f;                              // the chamber's flat back along the axis (local)
  std::vector<Vec3> restPositions;  // the rest shell's vertices (for the rigid fit of posed shells)
};

// Analyses a closed eyeball shell (seams allowed: vertices are welded by position). Throws
// InputError naming `what` when the limbus does not cut the shell into one cap and the rest, or
// the iris does not fit between the cornea and the chamber's back.
EyeModel analyseEye(const TriangleMesh& restShell, const EyeParams& params, const std::string& what);

// The iris's uvs map it onto a disc as an iris is photographed or painted, front view, the eye's
// up at the image's top: centre (0.5, 0.5), the root (under the limbus) on the circle of radius
// 0.5, the pupil margin on the circle of radius 0.5 kIrisUvPupilRadius, whatever the pupil's
// size. The sheet between them is stretched radially as the pupil widens or narrows, as Daugman
// 2004's "rubber sheet" model of the iris does, so a texture keeps its pupil and its features
// stay on the same fibres.
inline constexpr float kIrisUvPupilRadius = 0.34f;  // ~ the default 2 mm pupil in a 5.9 mm limbus

struct EyeMeshes {
  TriangleMesh cornea;  // closed, outward: cap + wall and back inside the ball
  TriangleMesh sclera;  // the shell outside the limbus (open where the cornea is)
  TriangleMesh iris;    // annulus, front side towards the cornea, with uvs (kIrisUvPupilRadius)
  TriangleMesh pupil;   // dark disc just behind the pupil opening, facing forward
};

// The shell (rest or posed, the rest shell's topology) cut at the limbus: the model's crossings
// added as vertices (positions and, when the shell has them, normals interpolated) and its
// triangles replaced by cutIndices.
TriangleMesh cutAtLimbus(const EyeModel& model, const TriangleMesh& shell);

// The rigid motion (rotation + translation, Umeyama 1991 without scale) that best carries the
// rest shell's vertices onto the posed shell's.
Affine3 eyeMotion(const EyeModel& model, const TriangleMesh& posedShell);

// The eye on a posed shell (same topology as the rest shell).
EyeMeshes buildEye(const EyeModel& model, const TriangleMesh& posedShell);

}  // namespace lacrima
