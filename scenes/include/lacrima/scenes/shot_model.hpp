#pragma once
// The Shot: everything a shot file says, checked and in lacrima's units (metres, radians where
// the renderer wants them, linear RGB), plus the external files it names, loaded once.
// Plain data: loadShot() fills it, a FrameBuilder (frame_builder.hpp) reads it and keeps the
// simulations it advances from frame to frame. docs/shot-format.md describes the file.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lacrima/flesh/flesh_simulation.hpp"
#include "lacrima/flesh/flesh_volume.hpp"
#include "lacrima/face/detail_patterns.hpp"
#include "lacrima/tears/dripping_tear.hpp"
#include "lacrima/face/eye.hpp"
#include "lacrima/face/eyelashes.hpp"
#include "lacrima/rig/face_controls.hpp"
#include "lacrima/rig/face_rig.hpp"
#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/base/math.hpp"
#include "lacrima/rig/region_refinement.hpp"
#include "lacrima/tears/shedding_tear.hpp"
#include "lacrima/mesh/surface_flow.hpp"
#include "lacrima/liquid/liquid_tear.hpp"
#include "lacrima/mesh/surface_region.hpp"
#include "lacrima/materials/material.hpp"
#include "lacrima/renderer/environment.hpp"
#include "lacrima/renderer/frame.hpp"
#include "lacrima/sph/dfsph.hpp"
#include "lacrima/scenes/animated_value.hpp"
#include "lacrima/scenes/shot.hpp"  // Diagnostic (shot.hpp includes this file after defining it)

namespace lacrima {

// Scale, then rotation, then translation: x_world = translate + rotation * (scale .* x).
struct ShotTransform {
  Vec3 translate = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();
  Vec3 scale = Vec3::Ones();

  Affine3 matrix() const;
};

// The camera as the shot file describes it, and the renderer camera derived from it at load.
struct ShotCamera {
  enum class Kind { LookAt, Gltf };
  Kind kind = Kind::LookAt;
  // Kind::LookAt
  Vec3 position = Vec3::Zero();
  Vec3 lookAt = Vec3(0, 0, -1);
  Vec3 up = Vec3(0, 1, 0);
  // Kind::Gltf: a camera of one of the shot's assets (the asset's transform applies)
  std::string gltfAsset;   // ShotAsset::name
  std::string gltfCamera;  // GltfCamera::name
  // Field of view: exactly one of these, or neither for a glTF camera (its yfov is used).
  std::optional<float> fovDegrees;     // vertical
  std::optional<float> focalLengthMm;  // with sensorHeightMm
  float sensorHeightMm = 24.0f;
  // Thin lens; pinhole when fStop is absent.
  std::optional<float> fStop;
  std::optional<float> focusDistance;  // metres; default: distance to lookAt
  // "focus": "surface": the renderer focuses each frame on the first surface on the view axis
  // (Camera::focusOnSurface); the distance above is then where it focuses when the axis meets nothing.
  bool focusOnSurface = false;

  Camera camera;  // derived at the first frame: what buildFrame hands to the renderer
  // Kind::LookAt: keyed position / look-at point (null curves when still). The up vector, field
  // of view and lens stay as written; the focus distance follows the look-at point unless given.
  AnimatedVec3 animatedPosition, animatedLookAt;
  bool animated() const { return animatedPosition.animated() || animatedLookAt.animated(); }
};

// A named, animatable channel of an asset: a blendshape weight, a rig joint channel or a
// control value. index: into the asset's targetNames, FaceControls::jointChannelNames or the
// controls.
struct AssetChannel {
  std::string name;
  size_t index = 0;
  AnimatedFloat value;
};

// A performance-capture weight track (Weise et al. 2011) bound to an asset: resampled to the shot's fps
// and optionally filtered at load; sample i plays at shot frame startFrame + i.
struct ShotPerformance {
  static constexpr size_t kNone = size_t(-1);
  std::filesystem::path file;  // resolved
  double startFrame = 1.0;
  // Per track channel, the asset blendshape it drives (index into targetNames) or the rig's joint
  // channel (index into FaceControls::jointChannelNames, e.g. head.rx from a tracker's head pose);
  // the other is kNone.
  std::vector<size_t> targets;
  std::vector<size_t> joints;
  std::vector<std::vector<float>> samples;  // samples[i][channel]

  // Adds the track's weights at `frame` (linear between samples, held outside) to `weights`.
  void addWeightsAt(double frame, std::vector<float>& weights) const;
  // The track's joint channels at `frame`: (joint channel, value) pairs.
  std::vector<std::pair<size_t, float>> jointsAt(double frame) const;
};

// One of the asset's glTF animations played in the shot ("animation" member of an asset).
struct ShotGltfAnimation {
  size_t index = 0;         // into gltf->animations
  double startFrame = 1.0;  // the shot frame at which the animation's time 0 plays
  double speed = 1.0;       // > 0
  bool loop = false;        // wrap instead of holding the last pose
  double fps = 24.0;        // the shot's frame rate
  double duration = 0.0;    // GltfAnimation::duration(), seconds

  // speed * (frame - startFrame) / fps, clamped to [0, duration], or wrapped into it with loop.
  double secondsAt(double frame) const;
};

// A light of the shot: the renderer's light as the file gives it (radiance already derived from
// power where given; centre at the first key) and what the shot keys on it.
struct ShotLight {
  AreaLight light;
  std::shared_ptr<const Vec3Curve> centerCurve;  // keyed centre in frames; null when still
  AnimatedFloat intensity{1.0f, nullptr};        // multiplies the radiance (default 1)

  // The light at a frame: its keyed centre, its radiance times its intensity there.
  AreaLight at(int frame) const;
};

struct ShotEnvironment {
  std::filesystem::path file;  // resolved
  float intensity = 1.0f;
  float rotationDegrees = 0.0f;               // about world +Y
  std::shared_ptr<const EnvironmentMap> map;  // loaded once by loadShot
};

// One glTF asset placed in the shot.
struct ShotAsset {
  std::string name;            // unique within the shot (default: file stem)
  std::filesystem::path file;  // resolved
  ShotTransform transform;
  // Binding of the asset's material or part names to shot material names, in file order.
  std::vector<std::pair<std::string, std::string>> materialBindings;
  // Static blendshape weights as written, in file order ...
  std::vector<std::pair<std::string, float>> blendshapes;
  // ... and indexed like gltf->targetNames (what applyMorphTargets wants).
  std::vector<float> weights;
  std::vector<std::string> hide;          // part names not rendered
  std::shared_ptr<const GltfAsset> gltf;  // loaded once by loadShot
  // Animation (issue "The face in motion"). Keyed blendshape weights (their static weight above
  // is the first key's value); a rig with joints and animator controls; a performance track.
  // All weight sources add, then each weight is clamped to [0, 1].
  std::vector<AssetChannel> animatedBlendshapes;
  std::shared_ptr<const FaceRig> rig;            // null: morph targets only, no joints
  std::vector<AssetChannel> joints;              // index into FaceControls::jointChannelNames
  std::shared_ptr<const FaceControls> controls;  // null when the asset declares none
  std::vector<AssetChannel> controlValues;       // index into controls->controls()
  std::optional<ShotPerformance> performance;
  // A glTF animation of the asset: its weights add to the other sources (then clamped), its
  // node motion moves the primitives before the asset transform.
  std::optional<ShotGltfAnimation> gltfAnimation;
  // True when the asset's shape changes over the shot's frames.
  bool animated() const;
  // Per primitive of gltf: index into the frame's material list (Shot::frameMaterials()),
  // or -1 when the primitive is hidden.
  std::vector<int> primitiveMaterials;
};

// Simple analytic or tessellated shapes (drops, floors, furnace spheres).
struct ShotShape {
  enum class Type { Sphere, Ellipsoid, Rectangle };
  Type type = Type::Sphere;
  Vec3 center = Vec3::Zero();
  float radius = 0.0f;               // Sphere
  Vec3 radii = Vec3::Ones();         // Ellipsoid semi-axes before rotation
  Mat3 rotation = Mat3::Identity();  // Ellipsoid
  Vec3 edgeU = Vec3(1, 0, 0);        // Rectangle: spans center +- edgeU/2 +- edgeV/2,
  Vec3 edgeV = Vec3(0, 1, 0);        //   normal normalize(edgeU x edgeV)
  std::string material;              // shot material name
  uint32_t materialId = 0;           // index into Shot::materials
  std::shared_ptr<const Vec3Curve> centerCurve;  // keyed center in frames; null when still
  // A shape attached to an asset's surface follows the skin: it is translated by the movement of
  // the surface point nearest to its center (found at the shot's first frame).
  struct Attachment {
    size_t asset = 0;      // index into Shot::assets
    size_t primitive = 0;  // of that asset
    uint32_t triangle = 0;
    Vec3 barycentric = Vec3(1, 0, 0);
    Vec3 reference = Vec3::Zero();  // the surface point at the first frame, world space
  };
  std::optional<Attachment> attachment;
  std::string attachAsset, attachPart;  // as written (resolved into attachment after the assets)
};

// A point on an asset's surface (triangle and barycentric coordinates of a posed primitive).
using ShotSurfacePoint = ShotShape::Attachment;

// Where a tear or a detail sits on a part, as written in the shot (docs/shot-format.md "Surface
// anchors"): a point near the skin (snapped to the nearest surface point of the part at the
// shot's first frame), a facial landmark of the asset, a vertex of the part, or a texture
// coordinate on the part. Resolved into a ShotSurfacePoint by loadShot.
struct ShotSurfaceAnchor {
  enum class Kind { Point, Landmark, Vertex, Uv };
  Kind kind = Kind::Point;
  Vec3 point = Vec3::Zero();  // Point: world space
  uint32_t index = 0;         // Landmark: index into GltfAsset::landmarks; Vertex: of the part's primitive
  Vec2 uv = Vec2::Zero();     // Uv: in the part's TEXCOORD_0
};

// A dripping tear (Lin & Cheng 2013 section 4.1, eq. 7; docs/shot-format.md "tears"): from startFrame on,
// a drop mesh at t = (frame - startFrame) / fps seconds leaves the skin point `origin` along
// `gravity`. Before startFrame there is no drop.
struct ShotTear {
  size_t asset = 0;       // index into Shot::assets
  std::string part;       // the part the start point is snapped to
  ShotSurfaceAnchor start;  // as written
  double startFrame = 1.0;
  DrippingTearParams params;
  Vec3 gravity = Vec3(0, -1, 0);  // non-zero; normalised by placeDrippingTear
  int rings = 32, segments = 48;
  std::string material;
  uint32_t materialId = 0;
  // Resolved by loadShot: the nearest surface point of the part to `start` at the shot's first
  // frame, and where that skin point is at startFrame (the drop leaves from there).
  ShotSurfacePoint surfacePoint;
  Vec3 origin = Vec3::Zero();

  // Seconds since the drop started at a (fractional) frame.
  double secondsAt(double frame, double fps) const { return (frame - startFrame) / fps; }
};

// A shedding tear (Lin & Cheng 2013 section 4.2; docs/shot-format.md "tears"): a strip of water running
// over the skin along `path`, grown to arc length h = start + speed t at t = (frame - startFrame)
// / fps seconds, placed on the part's posed primitive (after details) so it follows the face.
struct ShotSheddingTear {
  size_t asset = 0;            // index into Shot::assets
  std::string part;            // the part the path is snapped to
  std::vector<Vec3> path;      // as written: >= 2 world points near the skin at the first frame
  double startFrame = 1.0;
  SheddingTearParams params;   // "skinRoughness" is params.noiseDensity
  std::string material;
  uint32_t materialId = 0;
  std::string pointer;         // the tear in the shot file ("/tears/2"), for problems found resolving it
  // Resolved by loadShot from the part posed at the shot's first frame (the rest skin): the one
  // primitive all path points snap to, the rest skin's triangles around the path (Lin & Cheng 2013
  // section 4.2 step 1: the extracted region) and the snapped path on that region.
  size_t primitive = 0;
  std::shared_ptr<const SurfaceRegion> region;
  std::vector<SurfacePoint> regionPath;

  // Seconds since the tear started at a (fractional) frame.
  double secondsAt(double frame, double fps) const { return (frame - startFrame) / fps; }
};

class LiquidTearSurface;  // liquid_tear.hpp

// A liquid tear (docs/shot-format.md "Liquid tears"): tear fluid welling at a skin point
// and running down the flow path from it as beads that stick, slide, leave a drying film, hang and
// drip (LiquidTearSimulation, liquid_tear.hpp). The path is traced again at every integer frame on a
// smoothed copy of the part posed there (its courses, LiquidTearCourses in liquid_tear.hpp, which a
// FrameBuilder keeps), kept in surface coordinates, so its beads ride the posed skin and turn with
// the face. The liquid state at
// a frame is simulated from simulationStartFrame (t = 0: the shot's first frame, or the welling
// start when that is earlier, so a shot can begin mid-cry) to t = (frame - simulationStartFrame) /
// fps seconds, each step on the course of its nearest frame: a pure function of the frame.
// A skin region with its own contact angles for a liquid tear ("contactAngleRegions"): the path
// pieces that start within `radius` (straight-line distance, on the pose the course was traced
// on) of the centre use `contactAngles` (LiquidTearParams::contactAngleRegions, same index).
struct ShotContactAngleRegion {
  ShotSurfaceAnchor center;             // as written, on the tear's part
  double radius = 0.0;                  // metres, > 0
  ContactAngleHysteresis contactAngles;  // radians
  ShotSurfacePoint centerPoint;         // resolved by loadShot (on the source's primitive)
};

struct ShotLiquidTear {
  size_t asset = 0;              // index into Shot::assets
  std::string part;              // the part the source lies on and the path runs over
  ShotSurfaceAnchor source;      // as written
  Vec3 gravity = Vec3(0, -1, 0);  // non-zero; only its direction matters
  float maxLength = 0.12f;       // metres of flow path at most
  LiquidTearParams params;       // SI units (the file's uL and degrees converted; welling times from t = 0)
  // "contactAngleRegions", in list order (params.contactAngleRegions holds their angles); the first
  // that contains a path sample gives it its angles.
  std::vector<ShotContactAngleRegion> contactAngleRegions;
  // "trailRefinement": levels of linear refinement of the skin along the path at load (0: none).
  int trailRefinementLevels = 2;
  // Set by the trail refinement (liquid_trail_refinement.hpp), per primitive of the asset (null or
  // short: none): the first frame's smoothed skin carried over to the refined vertices, traced on
  // instead of smoothing the refined skin again.
  std::vector<std::shared_ptr<const std::vector<Vec3>>> smoothedSkins;
  double simulationStartFrame = 1.0;  // the frame at t = 0
  std::string material;
  uint32_t materialId = 0;
  std::string pointer;           // the tear in the shot file ("/tears/0"), for problems found resolving it
  // Resolved by loadShot (liquid_tear_resolve.hpp): the source on the first frame's skin, the flow
  // path from it at the first frame (its course there: points in the primitive's triangles, piece i
  // from points[i] to arrival[i + 1] in triangle points[i].triangle, arc lengths on the first
  // frame's real skin), and its stop reason.
  ShotSurfacePoint sourcePoint;
  FlowPath path;
  float smoothedPathLength = 0.0f;  // the path's length on the smoothed skin it was traced on
  LiquidTearInput input;            // the simulation's input (path samples of the first frame's course)
  // The lacrimal fluid strip that swells with the meniscus (meniscus_swelling.hpp): the asset's
  // primitive of part kLacrimalFluidPart nearest the source when within reach (-1: none), and the
  // falloff weight of each of its vertices (from the source, on the first frame's pose).
  int meniscusPrimitive = -1;
  std::vector<float> meniscusWeights;
  // Per vertex of the source's primitive: where the wet trail's edge lies beyond or short of the
  // film's half width (filmEdgeVariation in scenes/src/resolve/film_edge_variation.hpp); set by loadShot.
  std::vector<float> filmEdgeVariation;
  // "pinning": {"factor", "patchSize"}: the skin holds a contact line up to pinningFactor times
  // harder (and down to 1 / pinningFactor as hard) than the contact angles alone, in patches about
  // pinningPatchSize metres across (LiquidPathSample::pinning); 1: uniform skin.
  double pinningFactor = 1.0;
  double pinningPatchSize = 0.004;
  // Per vertex of the source's primitive, the factor there (liquid_tear_pinning.hpp); set by
  // loadShot when pinningFactor > 1, else empty.
  std::vector<float> pinning;
  // The surface the flow path is traced on at each frame (the source's primitive posed, and its
  // smoothed copy; liquid_tear.hpp); set by loadShot. `path` and `input.path` are the course traced
  // on it at frameStart.
  std::shared_ptr<const LiquidTearSurface> surface;
};

// Animated skin detail (Lin & Cheng 2013 section 3; docs/shot-format.md "details"): a sum of basic
// patterns displaced onto the part's posed primitives in an ellipse around a skin point, at
// frames startFrame..endFrame.
struct ShotDetail {
  std::vector<BasicDetailPattern> patterns;
  size_t asset = 0;
  std::string part;
  ShotSurfaceAnchor center;             // as written; resolved to a surface point at the first frame
  std::optional<Vec3> tangent;          // world direction projected to tangent x (default +x)
  float semiAxisA = 0.01f, semiAxisB = 0.01f;  // metres
  float innerRadius = 0.5f;
  float scale = 0.001f;                 // metres of displacement per unit of pattern height
  float coordinateScale = 1.0f;         // pattern units per metre in the tangent plane
  Vec2 patternOrigin = Vec2::Zero();    // the pattern's origin in the local (x, y), metres
  double startFrame = 1.0, endFrame = 1.0;
  AnimatedFloat amplitude{1.0f, nullptr};  // multiplies scale; >= 0
  ValidVertexSelection selection;
  // "subdivision": the part's mesh is refined this many levels around the region at load, before
  // anything is displaced (0: not refined).
  int subdivisionLevels = 0;
  RefinementScheme subdivisionScheme = RefinementScheme::Loop;
  ShotSurfacePoint surfacePoint;        // resolved by loadShot

  bool activeAt(int frame) const { return frame >= startFrame && frame <= endFrame; }
};

// Eyelashes of an eye (docs/shot-format.md "eyes"): tubes grown on the lash-card strips of `part`
// that lie around the eye; the cards themselves are not rendered.
struct ShotLashes {
  std::string part;
  LashParams params;
  uint32_t materialId = 0;
  // Resolved by loadShot on the cards posed at the shot's first frame.
  size_t primitive = 0;
  std::vector<LashStrip> strips;
  std::vector<Lash> lashes;
};

// An eye for close-ups (docs/shot-format.md "eyes"; eye.hpp): the eyeball shell `part` is cut at
// the limbus into cornea and sclera, an iris with depth and a pupil are added, all following the
// posed shell; the shell itself is not rendered.
struct ShotEye {
  size_t asset = 0;
  std::string part;
  EyeParams params;
  uint32_t corneaMaterial = 0, scleraMaterial = 0, irisMaterial = 0, pupilMaterial = 0;
  std::optional<ShotLashes> lashes;
  std::string pointer;  // the eye in the shot file ("/eyes/0"), for problems found resolving it
  // Resolved by loadShot on the shell posed at the shot's first frame.
  size_t primitive = 0;
  std::shared_ptr<const EyeModel> model;
};

// A sphere of a part's surface: all of the part's triangles whose corners lie within `radius` of
// the centre, on the first frame's pose (the skin a flesh is simulated under, the stretch of a face
// an SPH liquid collides with).
struct ShotSkinRegion {
  ShotSurfaceAnchor center;  // as written, on the flesh's part
  double radius = 0.0;       // metres, > 0
  ShotSurfacePoint centerPoint;  // resolved by loadShot
};

// Simulated flesh under part of a face (docs/shot-format.md "flesh"): a tetrahedral volume between
// the skin and the skin moved `volume.depth` inward, whose nodes the rig poses (the rest shape at
// each instant) and a finite-volume simulation moves (inertia: lag, jiggle, settling); the skin
// follows the simulated nodes. Simulated from the shot's first frame, so any frame renders alone.
// A shot's flesh dynamics unless it says otherwise. Rayleigh damping alpha = 4/s on the motion
// relative to the rig and beta = 2 ms: damping ratios alpha / (2 omega) + beta omega / 2 of ~0.1
// for a 10 Hz cheek wobble and ~0.2 for 30 Hz ripples (modelling choice: a few visible swings).
// Solver tolerances for pictures: Newton stops at 1 % of its first residual, each linear solve at
// 0.1 %; on the default shot's cheek the skin then moves within 0.024 mm of a solve to 1e-6 / 1e-8
// (of up to 1 mm), at a third of the cost. Both also stop once no node would move by more than
// 0.1 um: the default shot's skin then moves within 0.0025 mm of the solve without it (frames
// 26-30, the first sob, where the flesh moves it 0.18 mm), at a sixth of the conjugate gradients'
// iterations.
inline flesh::FleshDynamicsParams defaultShotFleshDynamics() {
  flesh::FleshDynamicsParams p;
  p.massDamping = 4.0;
  p.stiffnessDamping = 0.002;
  p.newtonTolerance = 1e-2;
  p.cgTolerance = 1e-3;
  p.positionTolerance = 1e-7;
  return p;
}

struct ShotFlesh {
  size_t asset = 0;
  std::string part;
  std::vector<ShotSkinRegion> regions;
  flesh::FleshVolumeSettings volume;
  flesh::FleshMaterial material = flesh::FleshMaterial::FixedCorotated;
  double youngsModulus = 3000.0;  // Pa
  double poissonRatio = 0.45;
  flesh::FleshDynamicsParams dynamics = defaultShotFleshDynamics();
  int substeps = 4;               // simulation steps per frame
  std::string pointer;            // "/flesh/0", for problems found resolving it
  // Resolved by loadShot (scenes/src/resolve/flesh_resolve.hpp): the primitive of the regions' centres, the
  // skin patch in it (positions of the shot's first frame), the volume under it (null: not
  // resolved, so not simulated).
  size_t primitive = 0;
  std::shared_ptr<const flesh::SkinPatch> patch;  // of the unrefined primitive, vertices welded by position
  std::shared_ptr<const flesh::FleshVolume> tetVolume;
  // Per vertex of the primitive as rendered (after refinement): its place in the volume (tet -1:
  // outside, not moved by the flesh).
  std::vector<flesh::TetEmbedding> skinEmbedding;
  // The asset as loaded, before any refinement of its skin: the one the simulation poses (the
  // volume's boundary is its tessellation).
  std::shared_ptr<const ShotAsset> unrefinedAsset;
  // Its simulation is a FrameBuilder's (frame_builder.hpp): advanced as frames are built.
};

// SPH liquid (docs/shot-format.md "sph"): fluid released as drops and blocks, simulated by DFSPH
// (lacrima/sph/dfsph.hpp) from its start frame against static colliders (shapes and asset parts
// at their pose of that frame), surfaced per frame (sph_surface.hpp) and rendered in
// its material, blurred by the particles' velocities.
struct ShotSphRelease {
  enum class Kind { Drop, Block };
  Kind kind = Kind::Drop;
  Vec3d center = Vec3d::Zero();  // Drop: a ball of particles
  double radius = 0.0;
  Vec3d min = Vec3d::Zero(), max = Vec3d::Zero();  // Block: a box of particles
  Vec3d velocity = Vec3d::Zero();  // m/s
  int frame = 0;                   // released at this frame (the simulation's start by default)
};

struct ShotSph {
  std::string material;
  uint32_t materialId = 0;
  sph::FluidParams fluid;
  // The frame the simulation starts at: the shot's first frame by default, or earlier (a pre-roll,
  // so that the shot opens on liquid already in motion). Colliders are posed there.
  int startFrame = 0;
  std::vector<ShotSphRelease> releases;
  std::vector<size_t> colliderShapes;               // indices into Shot::shapes
  std::vector<std::string> colliderShapePointers;  // each one's place in the file ("/sph/0/colliders/1")
  struct Part {
    size_t asset = 0;
    std::string part;
    std::vector<ShotSkinRegion> regions;  // none: the whole part
    std::string pointer;                  // "/sph/0/colliders/0"
  };
  std::vector<Part> colliderParts;
  double voxelsPerRadius = 1.5;  // surfacing resolution (sph::SurfaceParams)
  int smoothing = 32;  // mean-curvature steps: a drop a dozen particles across needs many to read as smooth water
  std::string pointer;  // "/sph/0"
  // Its simulation is a FrameBuilder's (frame_builder.hpp): advanced as frames are built.
};

struct Shot {
  std::filesystem::path path;  // the shot file, as given to loadShot
  int version = 1;

  int frameStart = 1;
  int frameEnd = 1;
  double fps = 24.0;

  // Resolved relative to the shot file's directory; '#' runs (or %04d) stand for the frame.
  std::string outputPattern;
  // "colorConfig" resolved; empty when the shot does not name one (the tool uses its default).
  std::filesystem::path ocioConfig;

  // frameNumber is set per frame by renderSettingsAt (shot.hpp); `lacrima render` applies its
  // command-line overrides here, once, after loading.
  RenderSettings render;
  ShotCamera camera;
  // Motion blur: the shutter is open from frame + open to frame + close (in frames, e.g.
  // {-0.25, 0.25} is a 180-degree shutter centred on the frame); none = no motion blur.
  std::optional<std::pair<double, double>> shutter;

  std::optional<ShotEnvironment> environment;
  Color background = Color(0, 0, 0);  // uniform radiance when there is no environment

  std::vector<Material> materials;       // from the shot file, in file order
  std::vector<Material> assetMaterials;  // glTF materials mapped automatically (unbound ones)
  std::vector<ShotLight> lights;
  std::vector<ShotAsset> assets;
  std::vector<ShotShape> shapes;
  std::vector<ShotTear> tears;                  // "dripping" tears
  std::vector<ShotSheddingTear> sheddingTears;  // "shedding" tears
  std::vector<ShotLiquidTear> liquidTears;      // "liquid" tears
  std::vector<ShotDetail> details;
  std::vector<ShotEye> eyes;
  std::vector<ShotFlesh> flesh;
  std::vector<ShotSph> sph;

  // Things that load but deserve a look (glTF loader caveats, environment texels that were
  // NaN/Inf/negative and set to 0), in file order. Each message starts with "warning: ". The tool
  // prints them.
  std::vector<Diagnostic> warnings;

  // Index of a shot material by name, or -1.
  int findMaterial(const std::string& name) const;
  // materials followed by assetMaterials: the list material ids index into.
  std::vector<Material> frameMaterials() const;
};

}  // namespace lacrima
