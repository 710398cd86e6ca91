#pragma once
// The liquid state of tears running along one flow path on the skin: the lacrimal meniscus filling
// and overflowing, beads that stick and slide, the wet trail they leave and its drying, hanging
// drops that detach and fall. Deterministic: the state at time t is simulated forward from t = 0
// with a fixed time step, so it is a pure function of t and the input (any frame can be computed
// alone and gives bitwise the same answer).
//
// Laws (SI units throughout; sources and modelling choices):
// * Welling: the source adds `rate` m^3/s during [start, end) to the meniscus. When the meniscus
//   holds overflowVolume it spills spillVolume as a new bead at s = 0 (modelling choice: the lid
//   margin releases a fixed portion, then refills).
// * Stick / slide: a bead at rest starts sliding when SlidingModel says so (Furmidge 1962,
//   ElSherbini & Jacobi 2006; see sessile_drop.hpp), tilt from the path's normal and gravity. On a
//   wet trail the retention force is scaled by 1 - wetness (1 - wetRetentionFactor), wetness =
//   min(1, film thickness / filmThickness) (modelling choice: a prewetted surface pins less).
// * Sliding speed: driving force minus retention balances the viscous dissipation in the contact
//   line wedges, F = 3 mu v ln(L/a) w / theta (de Gennes 1985, Rev. Mod. Phys. 57:827, wedge
//   dissipation, sec. IV; used for sliding drops by Kim, Lee & Kang 2002, J. Colloid Interface
//   Sci. 247:372), so v_terminal = theta_mean (F_drive - F_retention) / (3 mu ln(L/a) w), i.e.
//   Ca = mu v / gamma proportional to Bo sin(alpha) - Bo_c as in Podgorski, Flesselles & Limat
//   2001 (PRL 87:036102). It is the kinetic friction Li et al. 2023 (Nature Commun. 14:4571) measured
//   for drops sliding on many liquid/surface pairs, F_f = F_0 + beta w mu v with beta 20-200, here
//   F_0 the retention force and beta = 3 ln(L/a) / theta_mean (30 at the default angles; tested).
//   The speed relaxes to it with time constant speedRelaxationTime, and a
//   sliding bead moves at least at minSlideSpeed (modelling choice: it stops at the critical
//   volume in finite time instead of creeping towards it forever).
// * Trail: a sliding bead leaves a film of thickness filmThickness across its base width w
//   (slidingBaseWidth) on the dry skin: dV/ds = -h_f w(V), solved exactly per step with
//   w = c_w V^(1/3): V^(2/3) decreases by (2/3) h_f c_w ds (modelling choice for h_f, default
//   20 um). On film already present it only tops the film up to h_f w. It re-pins when
//   dropSlides turns false (it has thinned below the critical volume).
// * Drying: the film evaporates into still air, limited by the diffusion of its vapour
//   (film_evaporation.hpp: Picknett & Bexon 1977's flat disk, Buck 1981's vapour pressure, Massman
//   1998's diffusivity): each trail cell thins at 8 D dc / (pi rho_w w), w the cell's film width, so
//   it loses the same volume per length and time whatever its width (about 0.8 um/s on a 2 mm trail
//   at 33 degrees C skin in 22 degrees C air of 50 % humidity: 20 um dry in ~25 s). With
//   filmDryingTime > 0 the thickness decays as exp(-t / filmDryingTime) instead (a stand-in, e.g. to
//   dry a trail within a short test); the lost volume
//   is counted as dried.
// * Coalescence: a bead reaching the bead ahead merges with it (volumes add, momentum kept).
// * Drip: at the path's end or where the surface faces down (n . g_hat > overhangCosine) the bead
//   stops and hangs; where the surface faces down it detaches when its volume exceeds Tate's limit
//   2 pi r gamma / (rho g)
//   (hangingDropMaxVolume; Tate 1864), r = its spherical cap's base radius at the mean contact
//   angle, or hangingContactRadius when that is positive. The whole bead detaches (modelling
//   choice: no residual drop) and falls ballistically without drag: x(t) = x0 + g (t - t0)^2 / 2.
//   At a path end that does not face down (a pit, a wall where the path was cut) the bead pools
//   and grows: a pendant drop needs an overhang, and a drop let go there would fall through the
//   skin below it.
// * Falling drops ring in the Rayleigh/Lamb mode n = 2 about their velocity axis, damped by the
//   viscosity (drop_oscillation.hpp). The initial amplitude comes from the hanging bead as drawn
//   (beadShape at min(tilt, 90 degrees), long axis along the path): the ellipsoid of its half
//   extents (halfLength along the path, halfWidth across, height / 2 along the normal) released
//   as the spheroid whose polar semi-axis is that ellipsoid's extent along gravity and whose
//   volume is the ellipsoid's: eps0 = 2 (k - 1) / (k + 2), k = polar / equatorial, clamped to
//   [-0.5, 0.5] (modelling choice). On a wall the cap is long along gravity and thin out of the
//   skin: the drop leaves prolate (k ~ 1.5-2). Under a ceiling the drawn cap is flat against the
//   skin and the drop leaves oblate; a real pendant drop would be prolate (the cap model does not
//   draw a pendant drop's neck).
// * Rivulets (rivulet.hpp; LiquidTearParams::rivulet): while the source wells at formFlowRate or
//   faster, the overflowing meniscus runs down the path as one continuous rivulet instead of
//   spilling beads. Its liquid lives in the trail cells as a cross-section area A per cell and moves
//   as the kinematic wave A_t + Q(A)_s = 0 with Duffy & Moffatt 1995's small-width flux
//   Q = k A^2 at the cell's slope and receding contact angle (the rivulet's edges are laid by its
//   front and recede as it narrows; modelling choice), solved by first-order upwind finite volumes
//   with sub-steps that keep the Courant number 2 k A dt / cell at most 1/2 (monotone, and exactly
//   conservative: a cell never gives more than it holds). The rivulet wets the skin it covers (the
//   film is topped up to filmThickness across its width, from its own liquid), swallows the beads
//   it reaches, and feeds the bead hanging at the first drip site, which lets go by Tate's law as
//   before. When the flow drops (the source stops or slows), the rivulet drains and thins from the
//   top; a stretch that once carried breakFlowRate and now carries less breaks up into beads (a
//   modelling choice for the break-up criterion) spaced by rivuletBreakupSpacing at the width it
//   ran at, each bead at the volume-weighted centre of its stretch; they stick or slide as any bead.
// * A bead whose volume falls below minBeadVolume has run out: its rest joins the film (Dried).
// * Contact angles per skin region (water meets skin at 55-110 degrees, varying over the face): each
//   path piece has the contact angles of its start sample (LiquidPathSample::contactAngleRegion, an
//   index into params.contactAngleRegions; -1: params.contactAngles). Every law above that depends
//   on the angles (retention and the sliding criterion, terminal speed, base width c_w V^(1/3) and
//   so the trail's width and consumption, bead shape, hanging contact radius, detach amplitude) uses
//   the angles of the piece under the bead's centre, for the whole step. The angles change sharply
//   at a piece boundary (modelling choice: no blend across a region's border); a bead entering a
//   region of larger hysteresis can pin there, one of smaller hysteresis can set off.
//
// * Pinning: skin is not a uniform surface; its contact-angle hysteresis varies from place to
//   place (sebum, vellus hair, furrows, pores), so a bead slides on, slows, stops where the skin
//   holds harder and waits until it has grown (another bead merges into it) or the slope steepens.
//   Each path piece carries a factor on the retention force (LiquidPathSample::pinning, 1 by
//   default); the sliding criterion and the terminal speed use the factor of the piece under the
//   bead's centre, as they use its contact angles (modelling choice: the factor scales the
//   Furmidge / ElSherbini & Jacobi retention force as a local change of cos theta_R - cos theta_A
//   would; Joanny & de Gennes 1984, J. Chem. Phys. 81:552, for contact lines pinned by a
//   heterogeneous surface).
//
// * Re-routing (reroute): when the surface moves, the caller traces the path again and moves the
//   liquid onto the new course by an arc-length map (FlowPathTransfer: each bead and each trail
//   cell's film to the nearest point of the new course of the material point it sat on); volumes
//   are kept, film is spread over the image of its cell (it thins where the course stretched).
//
// Limits: one path at a time (beads do not leave it or branch; re-routing moves beads and film
// sideways onto the new course, with no motion of their own across it); the path is assumed to follow the steepest descent, so the whole along-surface
// gravity g sin(alpha) drives the bead along it; beads do not evaporate (minutes for uL drops);
// bead shape is reported for tilt min(alpha, 90 degrees); no drag on falling drops and only their
// n = 2 shape mode; the film is uniform across the width of the widest bead that wetted each cell.
#include <cstdint>
#include <functional>
#include <utility>
#include <numbers>
#include <vector>

#include "lacrima/liquid/drop_oscillation.hpp"
#include "lacrima/liquid/film_evaporation.hpp"
#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/liquid/rivulet.hpp"
#include "lacrima/liquid/sessile_drop.hpp"
#include "lacrima/mesh/surface_flow.hpp"

namespace lacrima {

// One sample of the path. The normal (unit, pointing out of the skin) applies to the straight
// piece from this sample to the next (flow paths are flat within each piece).
struct LiquidPathSample {
  double arcLength = 0.0;
  Vec3d position = Vec3d::Zero();
  Vec3d normal = Vec3d::UnitZ();
  // The contact angles of the piece from this sample to the next: an index into
  // LiquidTearParams::contactAngleRegions, or -1 for LiquidTearParams::contactAngles.
  int contactAngleRegion = -1;
  // How strongly the skin of the piece from this sample to the next pins a contact line: a factor
  // (finite, > 0) on the retention force there (1: the contact angles' hysteresis alone; > 1 a
  // patch that holds beads harder, < 1 one that lets them go sooner). See "Pinning" above.
  double pinning = 1.0;
};

// The samples of a traced flow path on `mesh` (the mesh it was traced on), each with the
// geometric normal of the triangle of the piece that starts there. Throws InputError for an empty path.
std::vector<LiquidPathSample> liquidPathFromFlowPath(const FlowPath& path, const TriangleMesh& mesh);

// The lacrimal meniscus filling at the start of the path.
struct WellingSource {
  double rate = 2.0 * kMicrolitre;             // m^3/s while welling (crying: several uL/s)
  double start = 0.0;                          // s
  double end = 1e30;                           // s
  double initialVolume = 0.0;                  // m^3 in the meniscus at t = 0
  double overflowVolume = 8.0 * kMicrolitre;   // the meniscus overflows when it holds this much
  double spillVolume = 6.0 * kMicrolitre;      // what leaves as a bead at each overflow (<= overflowVolume)
  // A rate that changes over time (a sob, crying that eases): keys (time s, rate m^3/s), straight
  // lines between them, held before the first and after the last; times strictly increasing,
  // rates finite and >= 0. Empty: `rate` throughout. Welling still only happens in [start, end).
  std::vector<std::pair<double, double>> rateKeys = {};

  // The rate at time t (0 outside [start, end)).
  double rateAt(double t) const;
  // The volume welled over [t0, t1]: the exact integral of rateAt (trapezoids between the keys).
  double volumeBetween(double t0, double t1) const;
};

// A bead already on the path at t = 0 (counted as source volume).
struct InitialBead {
  double arcLength = 0.0;
  double volume = 0.0;
};

struct LiquidTearParams {
  TearFluid fluid;
  ContactAngleHysteresis contactAngles{95.0 * std::numbers::pi / 180.0, 65.0 * std::numbers::pi / 180.0};
  // Contact angles of skin regions, used where a path sample names one (contactAngleRegion).
  std::vector<ContactAngleHysteresis> contactAngleRegions;
  double retentionFactor = kElSherbiniJacobiRetentionFactor;
  double viscosity = 1.5e-3;           // Pa s: tears 1-3 mPa s at high shear (assumption)
  double contactLineLogRatio = 13.8;   // ln(L/a), macroscopic over molecular cut-off (de Gennes 1985: 10-20)
  double speedRelaxationTime = 0.005;  // s
  double minSlideSpeed = 1e-3;         // m/s
  double wetRetentionFactor = 0.5;     // retention multiplier on a fully wet trail, (0, 1]
  double filmThickness = 20e-6;        // m, h_f
  double filmDryingTime = 0.0;         // s; > 0: exponential drying instead of evaporation
  EvaporationAir air;                  // the skin's and the air's temperature, the air's humidity
  double trailCellLength = 5e-4;       // m of arc length per film cell
  double overhangCosine = 0.5;         // n . g_hat above which the surface is an overhang (drip site)
  double hangingContactRadius = 0.0;   // m; 0: the cap's base radius
  double minBeadVolume = 0.01 * kMicrolitre;
  double timeStep = 1e-3;              // s
  WellingSource source;
  std::vector<InitialBead> initialBeads;
  // Rivulets (see "Rivulets" above), in m^3/s. formFlowRate 0: the tear never runs as a rivulet.
  // breakFlowRate in (0, formFlowRate], or 0 for half of formFlowRate.
  struct Rivulet {
    double formFlowRate = 0.0;
    double breakFlowRate = 0.0;
  } rivulet;
};

struct LiquidTearInput {
  std::vector<LiquidPathSample> path;          // at least 2 samples, arc length strictly increasing from 0
  Vec3d gravityDirection = -Vec3d::UnitY();    // any non-zero length; magnitude from params.fluid
  LiquidTearParams params;
};

enum class BeadPhase {
  Welling,   // pinned at the lid margin (s = 0), where later overflows merge into it
  Pinned,    // held by contact-angle hysteresis
  Sliding,
  Hanging,   // at a drip site (overhang or path end), growing until Tate's limit
  Detached,  // fell as a FallingDrop (volume 0)
  Merged,    // coalesced into the bead ahead, mergedInto (volume 0)
  Dried,     // ran out below minBeadVolume; its rest joined the film (volume 0)
  InRivulet, // reached by a rivulet, which took its liquid (volume 0)
};
const char* beadPhaseName(BeadPhase phase);
// Welling, Pinned, Sliding or Hanging: a bead that holds liquid.
bool isLiveBeadPhase(BeadPhase phase);

// A bead; beads keep their index (id) for life. Detached, Merged and Dried beads have volume 0
// (their liquid is a drop, another bead, or film).
struct Bead {
  double arcLength = 0.0;
  double speed = 0.0;   // m/s along the path
  double volume = 0.0;  // m^3
  BeadPhase phase = BeadPhase::Pinned;
  double birthTime = 0.0;  // end of the step in which it overflowed (0 for initial beads)
  int mergedInto = -1;  // bead id, for Merged
};

struct FallingDrop {
  int beadId = 0;
  double detachTime = 0.0;
  Vec3d detachCentre = Vec3d::Zero();
  Vec3d detachVelocity = Vec3d::Zero();  // a hanging bead is at rest: zero
  double volume = 0.0;
  DropOscillation oscillation;  // its n = 2 ringing from detachTime on
};

// Bead as the renderer needs it.
struct BeadView {
  int id = 0;
  BeadPhase phase = BeadPhase::Pinned;
  double arcLength = 0.0;
  double speed = 0.0;
  double volume = 0.0;
  Vec3d position = Vec3d::Zero();  // on the path
  Vec3d normal = Vec3d::UnitZ();
  double tilt = 0.0;               // radians from the horizontal, [0, pi]
  double contactAngle = 0.0;       // radians: the mean of the contact angles where the bead sits
  BeadShape shape;                 // beadShape at contactAngle and min(tilt, 90 degrees)
};

struct DropView {
  int beadId = 0;
  Vec3d centre = Vec3d::Zero();
  Vec3d velocity = Vec3d::Zero();
  double volume = 0.0;
  double radius = 0.0;  // equivalent sphere
  Vec3d axis = -Vec3d::UnitY();  // unit: along the velocity (gravity while it is still at rest)
  double amplitude = 0.0;        // mode-2 amplitude eps at this time (> 0 prolate along axis)
  double amplitudeEnvelope = 0.0;  // eps0 exp(-t / tau): the ringing's size, without its phase
  SpheroidAxes axes;             // modeTwoSpheroid(radius, amplitude): a^2 c = radius^3
};

// A point along a rivulet: its cross-section there (a parabola of this half-width and middle depth,
// rivulet.hpp) at a trail cell's centre.
struct RivuletStation {
  double arcLength = 0.0;
  Vec3d position = Vec3d::Zero();  // on the path
  Vec3d normal = Vec3d::UnitZ();
  double halfWidth = 0.0;  // m
  double height = 0.0;     // m
};

// One unbroken stretch of rivulet from arc length `begin` to `end` (trail cell edges), with a
// station at each of its cells' centres (every cell of the stretch holds liquid).
struct RivuletView {
  double begin = 0.0, end = 0.0;
  double volume = 0.0;  // m^3
  std::vector<RivuletStation> stations;
};

struct LiquidTearState {
  double time = 0.0;
  double meniscusVolume = 0.0;
  std::vector<BeadView> beads;             // live beads only (volume > 0)
  std::vector<DropView> drops;
  std::vector<RivuletView> rivulets;       // from the source down
  std::vector<double> sampleFilmThickness;  // per path sample, m
};

// Where the liquid is; every term in m^3.
struct VolumeBudget {
  double source = 0.0;  // welled so far plus initial meniscus and beads
  double meniscus = 0.0;
  double beads = 0.0;
  double film = 0.0;
  double rivulet = 0.0;
  double detached = 0.0;
  double dried = 0.0;
  double accounted() const { return meniscus + beads + film + rivulet + detached + dried; }
  // |accounted - source| / source (0 for no source).
  double relativeImbalance() const;
};

// The forward simulation. Throws InputError for an invalid input (message names the field).
class LiquidTearSimulation {
 public:
  explicit LiquidTearSimulation(LiquidTearInput input);

  // Steps forward to the last step time <= t (t may not go backwards: InputError).
  void advanceTo(double t);
  void step();

  // Moves the liquid onto a new course: the flow path traced again on the surface as it has moved
  // (the face moves). newArcLength(s) is the arc length on `path` of the surface's material point at
  // arc length s of the current path (e.g. FlowPathTransfer). Every bead goes to the image of its
  // arc length (a bead at the source stays at 0); a hanging bead that is no longer at a drip site is
  // released (it slides on if the new slope carries it); each trail cell's film is spread over the
  // image of the cell (volume and width kept, so the film thins where the course stretched). Volumes
  // are unchanged. Throws InputError for an invalid path (the simulation is then unchanged).
  void reroute(std::vector<LiquidPathSample> path, const std::function<double(double)>& newArcLength);
  const std::vector<LiquidPathSample>& path() const { return input_.path; }

  double time() const { return double(steps_) * input_.params.timeStep; }
  long long steps() const { return steps_; }
  double meniscusVolume() const { return meniscus_; }
  const std::vector<Bead>& beads() const { return beads_; }
  const std::vector<FallingDrop>& drops() const { return drops_; }
  const std::vector<double>& cellFilmVolume() const { return cellVolume_; }
  // The rivulet's liquid per trail cell (m^3); all 0 without a rivulet.
  const std::vector<double>& cellRivuletVolume() const { return rivuletVolume_; }
  // Whether the source now overflows as a rivulet: welling at rivulet.formFlowRate or faster.
  bool wellsAsRivulet() const;
  // The rivulet's flow law (rivulet.hpp) at arc length s: its slope and receding contact angle.
  RivuletFlow rivuletFlowAt(double arcLength) const;
  VolumeBudget budget() const;

  // Film thickness (m) at arc length s; 0 off the path.
  double filmThicknessAt(double arcLength) const;
  // An upper bound of filmThicknessAt(s) for every s in [s0, s1] (also for an s one rounding off
  // either end): the thickest cell from the one before s0's to the one after s1's.
  double maxFilmThicknessBetween(double s0, double s1) const;
  // Width (m) of the film at arc length s: the widest bead base that wetted its cell; 0 off the
  // path or where no film was laid.
  double filmWidthAt(double arcLength) const;
  // The film cell at arc length s, or -1 off the path; with filmThicknessOfCell and
  // filmWidthOfCell it answers filmThicknessAt and filmWidthAt with one index, for callers that ask
  // millions of times a frame and tabulate the cells once.
  long filmCellAt(double arcLength) const;
  double filmThicknessOfCell(size_t cell) const { return cellThickness(cell); }
  double filmWidthOfCell(size_t cell) const { return cellWidth_[cell]; }
  size_t filmCellCount() const { return cellVolume_.size(); }
  // The state for rendering at time t, which must lie in the current step: advanceTo(t) first
  // (InputError otherwise). Beads are as of the last step; drops are placed at exactly t.
  LiquidTearState state(double t) const;

  // Terminal sliding speed (m/s, >= 0, before the minSlideSpeed floor) of a bead of this volume
  // at this tilt with this wetness in [0, 1], at params.contactAngles (the *At forms: at the
  // contact angles and pinning of arc length s).
  double terminalSpeed(double volume, double tilt, double wetness) const;
  bool slides(double volume, double tilt, double wetness) const;
  double terminalSpeedAt(double arcLength, double volume, double tilt, double wetness) const;
  bool slidesAt(double arcLength, double volume, double tilt, double wetness) const;
  // The contact angles at arc length s (of the piece there).
  const ContactAngleHysteresis& contactAnglesAt(double arcLength) const;
  // Surface tilt from the horizontal (radians, [0, pi]) and overhang test at arc length s.
  double tiltAt(double arcLength) const;

 private:
  void well();
  // Rivulets (liquid_tear_rivulet.cpp), in the order step() runs them.
  void flowRivulet();
  void wetUnderRivulet();
  void joinRivulet();
  void breakRivulet();
  size_t rivuletCellEnd() const;  // cells [0, end) carry a rivulet: those starting before the first drip site
  double dripSiteOfRivulet() const;
  void feedDripSite(double volume);
  void breakStretch(size_t first, size_t last, double halfWidth);
  void rivuletViews(LiquidTearState& state) const;
  // The flow law at each trail cell's centre, tabulated for the current course (at construction and
  // after each reroute): the rivulet asks for it many times a step.
  void tabulateRivuletCells();
  void moveBead(Bead& bead, int id);
  void depositTrail(Bead& bead, int id, double distance);
  void runOut(Bead& bead, int id);
  void coalesce();
  void detachIfHeavy(Bead& bead, int id);
  double detachAmplitude(const Bead& bead) const;
  void dryFilm();
  void rerouteFilm(const std::function<double(double)>& image, double newLength);
  double hangingLimit(double volume, double arcLength) const;
  double baseRadius(double volume, double arcLength) const;
  // Index into sliding_ / widthPerCubeRoot_ of the piece at arc length s (0: params.contactAngles).
  size_t anglesAt(double arcLength) const;
  double terminalSpeedWith(size_t angles, double volume, double tilt, double wetness, double pinning = 1.0) const;
  bool slidesWith(size_t angles, double volume, double tilt, double wetness, double pinning = 1.0) const;
  double retentionScale(double wetness) const;
  double pinningAt(double arcLength) const;
  double wetnessAhead(const Bead& bead, int id) const;
  bool isDripSite(double arcLength) const;
  // The skin at arcLength faces down (n . g_hat > overhangCosine): a hanging bead can let go there.
  bool facesDown(double arcLength) const;
  double nextDripSite(double from, double to) const;
  size_t pieceAt(double arcLength) const;
  Vec3d positionAt(double arcLength) const;
  size_t cellAt(double arcLength) const;
  double cellLength(size_t cell) const;
  double cellThickness(size_t cell) const;

  LiquidTearInput input_;
  // Per contact angles: [0] params.contactAngles, [1 + i] params.contactAngleRegions[i].
  std::vector<SlidingModel> sliding_;
  std::vector<double> widthPerCubeRoot_;  // c_w in w = c_w V^(1/3)
  Vec3d gHat_;
  double pathLength_ = 0.0;
  // Film volume a trail cell loses to evaporation per metre of its length and second (m^2/s):
  // the thinning speed times the width, which does not depend on the width.
  double evaporationPerLength_ = 0.0;
  long long steps_ = 0;
  double meniscus_ = 0.0;
  double sourced_ = 0.0;
  double detached_ = 0.0;
  double dried_ = 0.0;
  std::vector<Bead> beads_;
  std::vector<FallingDrop> drops_;
  std::vector<double> cellVolume_;  // film volume per trail cell
  std::vector<double> cellWidth_;   // widest bead base that wetted the cell
  std::vector<int> cellDepositor_;  // bead that last laid film there (-1: none)
  std::vector<double> cellOwnVolume_;  // the part of the film that bead laid
  std::vector<double> rivuletVolume_;  // rivulet liquid per trail cell
  std::vector<double> rivuletPeakFlux_;  // the largest flux the cell's rivulet has carried (0: none now)
  double breakFlowRate_ = 0.0;
  std::vector<RivuletFlow> cellFlow_;           // per trail cell, at its centre
  std::vector<double> cellFluxCoefficient_;     // k of Q = k A^2 per trail cell
};

// The number of steps of `timeStep` a simulation takes to reach t (advanceTo(t) takes this many).
// Throws InputError for a t that is not finite and >= 0.
long long liquidTearStepsTo(double t, double timeStep);

// The state at time t of a fresh simulation (simulated from t = 0).
LiquidTearState simulateLiquidTear(const LiquidTearInput& input, double t);
VolumeBudget liquidTearVolumeBudget(const LiquidTearInput& input, double t);

}  // namespace lacrima
