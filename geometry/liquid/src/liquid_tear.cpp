#include "lacrima/liquid/liquid_tear.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {

namespace {

// |eps0| at most this (axis ratio 2 prolate, 0.4 oblate): beyond it the single n = 2 mode is a poor
// description of the released drop (modelling choice).
constexpr double kMaxDetachAmplitude = 0.5;

void requireFinite(double value, const char* what) {
  if (!std::isfinite(value)) throw InputError(fmt::format("liquid tear: {} must be finite, got {}", what, value));
}

void requirePositiveTearParameter(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0))
    throw InputError(fmt::format("liquid tear: {} must be finite and positive, got {}", what, value));
}

void requireNonNegative(double value, const char* what) {
  if (!(std::isfinite(value) && value >= 0.0))
    throw InputError(fmt::format("liquid tear: {} must be finite and >= 0, got {}", what, value));
}

void validatePath(std::vector<LiquidPathSample>& path, size_t regionCount) {
  if (path.size() < 2)
    throw InputError(fmt::format("liquid tear: the path needs at least 2 samples, got {}", path.size()));
  if (path.front().arcLength != 0.0)
    throw InputError(fmt::format("liquid tear: the path's first arc length must be 0, got {}", path.front().arcLength));
  for (size_t i = 0; i < path.size(); ++i) {
    LiquidPathSample& sample = path[i];
    if (!sample.position.allFinite() || !sample.normal.allFinite() || !(sample.normal.norm() > 0.0))
      throw InputError(fmt::format("liquid tear: path sample {} needs a finite position and a non-zero normal", i));
    sample.normal.normalize();
    requireFinite(sample.arcLength, "path arc length");
    if (!(std::isfinite(sample.pinning) && sample.pinning > 0.0))
      throw InputError(fmt::format("liquid tear: path sample {} needs a finite pinning factor > 0, got {}", i, sample.pinning));
    if (sample.contactAngleRegion < -1 || sample.contactAngleRegion >= int(regionCount))
      throw InputError(fmt::format("liquid tear: path sample {} names contact angle region {}, there are {}", i,
                                   sample.contactAngleRegion, regionCount));
    if (i > 0 && !(sample.arcLength > path[i - 1].arcLength))
      throw InputError(fmt::format("liquid tear: path arc length must increase strictly, sample {} has {} after {}", i,
                                   sample.arcLength, path[i - 1].arcLength));
  }
}

void validateSource(const WellingSource& source) {
  requireNonNegative(source.rate, "welling rate");
  requireFinite(source.start, "welling start");
  if (!(source.end >= source.start))
    throw InputError(fmt::format("liquid tear: welling end ({}) must not be before its start ({})", source.end, source.start));
  requireNonNegative(source.initialVolume, "initial meniscus volume");
  requirePositiveTearParameter(source.overflowVolume, "overflow volume");
  requirePositiveTearParameter(source.spillVolume, "spill volume");
  for (size_t i = 0; i < source.rateKeys.size(); ++i) {
    const auto& [time, rate] = source.rateKeys[i];
    requireFinite(time, "welling rate key time");
    requireNonNegative(rate, "welling rate key rate");
    if (i > 0 && !(time > source.rateKeys[i - 1].first))
      throw InputError(fmt::format("liquid tear: welling rate key times must increase strictly, key {} has {} s after {} s",
                                   i, time, source.rateKeys[i - 1].first));
  }
  if (source.spillVolume > source.overflowVolume)
    throw InputError(fmt::format("liquid tear: spill volume {} must not exceed the overflow volume {}", source.spillVolume,
                                 source.overflowVolume));
}

void validateParams(const LiquidTearParams& p, double pathLength) {
  requirePositiveTearParameter(p.viscosity, "viscosity");
  requirePositiveTearParameter(p.contactLineLogRatio, "contact line log ratio");
  requirePositiveTearParameter(p.speedRelaxationTime, "speed relaxation time");
  requireNonNegative(p.minSlideSpeed, "minimum slide speed");
  if (!(p.wetRetentionFactor > 0.0 && p.wetRetentionFactor <= 1.0))
    throw InputError(fmt::format("liquid tear: wet retention factor must be in (0, 1], got {}", p.wetRetentionFactor));
  requirePositiveTearParameter(p.filmThickness, "film thickness");
  requireNonNegative(p.filmDryingTime, "film drying time");
  validateEvaporationAir(p.air);
  requirePositiveTearParameter(p.trailCellLength, "trail cell length");
  if (!(p.overhangCosine >= -1.0 && p.overhangCosine <= 1.0))
    throw InputError(fmt::format("liquid tear: overhang cosine must be in [-1, 1], got {}", p.overhangCosine));
  requireNonNegative(p.hangingContactRadius, "hanging contact radius");
  requirePositiveTearParameter(p.minBeadVolume, "minimum bead volume");
  requirePositiveTearParameter(p.timeStep, "time step");
  validateSource(p.source);
  requireNonNegative(p.rivulet.formFlowRate, "rivulet form flow rate");
  requireNonNegative(p.rivulet.breakFlowRate, "rivulet break flow rate");
  if (p.rivulet.breakFlowRate > p.rivulet.formFlowRate)
    throw InputError(fmt::format("liquid tear: the rivulet's break flow rate {} must not exceed its form flow rate {}",
                                 p.rivulet.breakFlowRate, p.rivulet.formFlowRate));
  if (p.rivulet.formFlowRate > 0.0) {
    // The lubrication rivulet (rivulet.hpp) needs an edge angle below 90 degrees.
    auto checkReceding = [](const ContactAngleHysteresis& angles, const char* where) {
      if (!(angles.receding < 0.5 * std::numbers::pi))
        throw InputError(fmt::format("liquid tear: a rivulet needs receding contact angles below 90 degrees; {} has {} "
                                     "degrees",
                                     where, angles.receding * 180.0 / std::numbers::pi));
    };
    checkReceding(p.contactAngles, "contactAngles");
    for (const ContactAngleHysteresis& angles : p.contactAngleRegions) checkReceding(angles, "a contact angle region");
  }
  for (const InitialBead& bead : p.initialBeads) {
    requirePositiveTearParameter(bead.volume, "initial bead volume");
    if (!(bead.arcLength >= 0.0 && bead.arcLength <= pathLength))
      throw InputError(fmt::format("liquid tear: initial bead arc length {} is outside the path [0, {}]", bead.arcLength,
                                   pathLength));
  }
}

long long stepsFor(double t, double dt) {
  if (!(std::isfinite(t) && t >= 0.0)) throw InputError(fmt::format("liquid tear: time must be finite and >= 0, got {}", t));
  return (long long)std::floor(t / dt + 1e-9);
}

bool isLive(const Bead& bead) { return isLiveBeadPhase(bead.phase); }

double equivalentRadius(double volume) { return std::cbrt(3.0 * volume / (4.0 * std::numbers::pi)); }

}  // namespace

const char* beadPhaseName(BeadPhase phase) {
  switch (phase) {
    case BeadPhase::Welling: return "welling";
    case BeadPhase::Pinned: return "pinned";
    case BeadPhase::Sliding: return "sliding";
    case BeadPhase::Hanging: return "hanging";
    case BeadPhase::Detached: return "detached";
    case BeadPhase::Merged: return "merged";
    case BeadPhase::Dried: return "dried";
    case BeadPhase::InRivulet: return "in rivulet";
  }
  return "unknown";
}

std::vector<LiquidPathSample> liquidPathFromFlowPath(const FlowPath& path, const TriangleMesh& mesh) {
  if (path.points.empty()) throw InputError("liquid tear: the flow path is empty");
  std::vector<LiquidPathSample> samples(path.points.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    samples[i].arcLength = path.arcLength[i];
    samples[i].position = path.positions[i].cast<double>();
    samples[i].normal = triangleNormal(mesh, path.points[i].triangle).cast<double>().normalized();
  }
  return samples;
}

bool isLiveBeadPhase(BeadPhase phase) {
  return phase == BeadPhase::Welling || phase == BeadPhase::Pinned || phase == BeadPhase::Sliding ||
         phase == BeadPhase::Hanging;
}

double VolumeBudget::relativeImbalance() const {
  return source > 0.0 ? std::abs(accounted() - source) / source : std::abs(accounted());
}

// ---- Set-up ---------------------------------------------------------------------------------------

LiquidTearSimulation::LiquidTearSimulation(LiquidTearInput input) : input_(std::move(input)) {
  validatePath(input_.path, input_.params.contactAngleRegions.size());
  pathLength_ = input_.path.back().arcLength;
  const LiquidTearParams& p = input_.params;
  validateParams(p, pathLength_);
  if (!input_.gravityDirection.allFinite() || !(input_.gravityDirection.norm() > 0.0))
    throw InputError("liquid tear: gravity direction must be finite and non-zero");
  gHat_ = input_.gravityDirection.normalized();
  evaporationPerLength_ = filmEvaporationSpeed(p.air, 1.0, p.fluid.density);  // speed x width at w = 1 m
  sliding_.push_back(SlidingModel{p.fluid, p.contactAngles, p.retentionFactor});
  for (const ContactAngleHysteresis& angles : p.contactAngleRegions)
    sliding_.push_back(SlidingModel{p.fluid, angles, p.retentionFactor});
  for (const SlidingModel& model : sliding_)  // slidingBaseWidth validates the model
    widthPerCubeRoot_.push_back(slidingBaseWidth(model, kMicrolitre) / std::cbrt(kMicrolitre));
  const size_t cells = size_t(std::ceil(pathLength_ / p.trailCellLength));
  cellVolume_.assign(std::max<size_t>(cells, 1), 0.0);
  cellWidth_.assign(cellVolume_.size(), 0.0);
  cellDepositor_.assign(cellVolume_.size(), -1);
  cellOwnVolume_.assign(cellVolume_.size(), 0.0);
  rivuletVolume_.assign(cellVolume_.size(), 0.0);
  rivuletPeakFlux_.assign(cellVolume_.size(), 0.0);
  breakFlowRate_ = p.rivulet.breakFlowRate > 0.0 ? p.rivulet.breakFlowRate : 0.5 * p.rivulet.formFlowRate;
  if (p.rivulet.formFlowRate > 0.0) tabulateRivuletCells();
  meniscus_ = p.source.initialVolume;
  sourced_ = meniscus_;
  for (const InitialBead& initial : p.initialBeads) {
    beads_.push_back(Bead{initial.arcLength, 0.0, initial.volume, BeadPhase::Pinned, 0.0, -1});
    sourced_ += initial.volume;
  }
}

// ---- Path queries ---------------------------------------------------------------------------------

size_t LiquidTearSimulation::pieceAt(double s) const {
  const auto& path = input_.path;
  const auto it = std::upper_bound(path.begin(), path.end(), s,
                                   [](double value, const LiquidPathSample& sample) { return value < sample.arcLength; });
  const size_t index = it == path.begin() ? 0 : size_t(it - path.begin()) - 1;
  return std::min(index, path.size() - 2);
}

Vec3d LiquidTearSimulation::positionAt(double s) const {
  const size_t i = pieceAt(s);
  const LiquidPathSample& a = input_.path[i];
  const LiquidPathSample& b = input_.path[i + 1];
  const double f = std::clamp((s - a.arcLength) / (b.arcLength - a.arcLength), 0.0, 1.0);
  return a.position + f * (b.position - a.position);
}

double LiquidTearSimulation::tiltAt(double s) const {
  // cos(alpha) = n . up = -n . g_hat: 0 for a floor, pi / 2 for a wall, pi for a ceiling.
  const double cosTilt = std::clamp(-input_.path[pieceAt(s)].normal.dot(gHat_), -1.0, 1.0);
  return std::acos(cosTilt);
}

bool LiquidTearSimulation::isDripSite(double s) const { return s >= pathLength_ || facesDown(s); }

bool LiquidTearSimulation::facesDown(double s) const {
  return input_.path[pieceAt(s)].normal.dot(gHat_) > input_.params.overhangCosine;
}

double LiquidTearSimulation::nextDripSite(double from, double to) const {
  // Pieces start at samples; the first overhanging piece beginning in (from, to], else the path's end.
  const auto& path = input_.path;
  for (size_t i = pieceAt(from) + 1; i + 1 < path.size() && path[i].arcLength <= to; ++i)
    if (path[i].normal.dot(gHat_) > input_.params.overhangCosine) return path[i].arcLength;
  return std::min(to, pathLength_);
}

size_t LiquidTearSimulation::cellAt(double s) const {
  return std::min(size_t(std::max(s, 0.0) / input_.params.trailCellLength), cellVolume_.size() - 1);
}

double LiquidTearSimulation::cellLength(size_t cell) const {
  const double begin = double(cell) * input_.params.trailCellLength;
  return std::min(input_.params.trailCellLength, pathLength_ - begin);
}

double LiquidTearSimulation::cellThickness(size_t cell) const {
  return cellWidth_[cell] > 0.0 ? cellVolume_[cell] / (cellWidth_[cell] * cellLength(cell)) : 0.0;
}

long LiquidTearSimulation::filmCellAt(double s) const {
  if (!(s >= 0.0 && s <= pathLength_)) return -1;
  return long(cellAt(s));
}

double LiquidTearSimulation::filmThicknessAt(double s) const {
  const long cell = filmCellAt(s);
  return cell < 0 ? 0.0 : cellThickness(size_t(cell));
}

double LiquidTearSimulation::maxFilmThicknessBetween(double s0, double s1) const {
  if (cellVolume_.empty()) return 0.0;
  const size_t first = cellAt(std::min(s0, s1)), last = cellAt(std::max(s0, s1));
  double thickest = 0.0;
  for (size_t cell = first > 0 ? first - 1 : 0; cell <= std::min(last + 1, cellVolume_.size() - 1); ++cell)
    thickest = std::max(thickest, cellThickness(cell));
  return thickest;
}

double LiquidTearSimulation::filmWidthAt(double s) const {
  const long cell = filmCellAt(s);
  return cell < 0 ? 0.0 : cellWidth_[size_t(cell)];
}

// Wetness met by the bead's front contact line (ignoring film the bead laid itself).
double LiquidTearSimulation::wetnessAhead(const Bead& bead, int id) const {
  const size_t cell = cellAt(std::min(bead.arcLength + baseRadius(bead.volume, bead.arcLength), pathLength_));
  if (cellDepositor_[cell] == id) return 0.0;
  return std::min(1.0, cellThickness(cell) / input_.params.filmThickness);
}

// ---- Laws -----------------------------------------------------------------------------------------

size_t LiquidTearSimulation::anglesAt(double s) const {
  return size_t(input_.path[pieceAt(s)].contactAngleRegion + 1);
}

const ContactAngleHysteresis& LiquidTearSimulation::contactAnglesAt(double s) const {
  return sliding_[anglesAt(s)].hysteresis;
}

double LiquidTearSimulation::baseRadius(double volume, double s) const {
  return 0.5 * widthPerCubeRoot_[anglesAt(s)] * std::cbrt(volume);
}

double LiquidTearSimulation::retentionScale(double wetness) const {
  return 1.0 - wetness * (1.0 - input_.params.wetRetentionFactor);
}

bool LiquidTearSimulation::slides(double volume, double tilt, double wetness) const {
  return slidesWith(0, volume, tilt, wetness);
}

bool LiquidTearSimulation::slidesAt(double s, double volume, double tilt, double wetness) const {
  return slidesWith(anglesAt(s), volume, tilt, wetness, pinningAt(s));
}

bool LiquidTearSimulation::slidesWith(size_t angles, double volume, double tilt, double wetness, double pinning) const {
  const SlidingModel& model = sliding_[angles];
  // Exactly the SlidingModel criterion on dry skin of the contact angles' own hysteresis.
  if (wetness <= 0.0 && pinning == 1.0) return dropSlides(model, volume, tilt);
  const double drive = model.fluid.density * volume * model.fluid.gravity * std::sin(tilt);
  return drive > 0.0 && drive >= pinning * retentionScale(wetness) * retentionForce(model, volume);
}

double LiquidTearSimulation::pinningAt(double s) const { return input_.path[pieceAt(s)].pinning; }

double LiquidTearSimulation::terminalSpeed(double volume, double tilt, double wetness) const {
  return terminalSpeedWith(0, volume, tilt, wetness);
}

double LiquidTearSimulation::terminalSpeedAt(double s, double volume, double tilt, double wetness) const {
  return terminalSpeedWith(anglesAt(s), volume, tilt, wetness, pinningAt(s));
}

double LiquidTearSimulation::terminalSpeedWith(size_t angles, double volume, double tilt, double wetness,
                                               double pinning) const {
  // de Gennes 1985 wedge dissipation: F_drive - F_retention = 3 mu v ln(L/a) w / theta_mean.
  const LiquidTearParams& p = input_.params;
  const SlidingModel& model = sliding_[angles];
  const double drive = model.fluid.density * volume * model.fluid.gravity * std::sin(tilt);
  const double excess = drive - pinning * retentionScale(wetness) * retentionForce(model, volume);
  const double thetaMean = 0.5 * (model.hysteresis.advancing + model.hysteresis.receding);
  const double width = slidingBaseWidth(model, volume);
  return std::max(0.0, thetaMean * excess / (3.0 * p.viscosity * p.contactLineLogRatio * width));
}

// ---- Stepping -------------------------------------------------------------------------------------

void LiquidTearSimulation::advanceTo(double t) {
  const long long target = stepsFor(t, input_.params.timeStep);
  if (target < steps_)
    throw InputError(fmt::format("liquid tear: cannot go back in time from {} s to {} s", time(), t));
  while (steps_ < target) step();
}

void LiquidTearSimulation::step() {
  well();
  if (input_.params.rivulet.formFlowRate > 0.0) {
    flowRivulet();
    wetUnderRivulet();
    joinRivulet();
    breakRivulet();
  }
  for (size_t id = 0; id < beads_.size(); ++id) {
    Bead& bead = beads_[id];
    if (bead.phase == BeadPhase::Hanging || !isLive(bead)) continue;
    moveBead(bead, int(id));
  }
  coalesce();
  for (size_t id = 0; id < beads_.size(); ++id)
    if (beads_[id].phase == BeadPhase::Hanging) detachIfHeavy(beads_[id], int(id));
  dryFilm();
  ++steps_;
}

void LiquidTearSimulation::well() {
  const WellingSource& source = input_.params.source;
  const double t0 = time();
  const double t1 = t0 + input_.params.timeStep;
  const double added = source.volumeBetween(t0, t1);
  meniscus_ += added;
  sourced_ += added;
  // Welling fast enough, the overflow runs on as a rivulet from the lid margin (the path's start).
  if (wellsAsRivulet() && meniscus_ > source.overflowVolume) {
    rivuletVolume_[0] += meniscus_ - source.overflowVolume;
    meniscus_ = source.overflowVolume;
    return;
  }
  // The meniscus overflows over the lid margin: a bead of spillVolume leaves (merges with a bead
  // still sitting at the lid through coalesce()).
  while (meniscus_ >= source.overflowVolume) {
    meniscus_ -= source.spillVolume;
    beads_.push_back(Bead{0.0, 0.0, source.spillVolume, BeadPhase::Welling, t1, -1});
  }
}

void LiquidTearSimulation::moveBead(Bead& bead, int id) {
  const LiquidTearParams& p = input_.params;
  if (isDripSite(bead.arcLength)) {
    bead.phase = BeadPhase::Hanging;
    bead.speed = 0.0;
    return;
  }
  const double tilt = tiltAt(bead.arcLength);
  const double wetness = wetnessAhead(bead, id);
  const size_t angles = anglesAt(bead.arcLength);
  const double pinning = pinningAt(bead.arcLength);
  if (!slidesWith(angles, bead.volume, tilt, wetness, pinning)) {
    bead.phase = bead.arcLength == 0.0 ? BeadPhase::Welling : BeadPhase::Pinned;
    bead.speed = 0.0;
    return;
  }
  bead.phase = BeadPhase::Sliding;
  const double target = std::max(terminalSpeedWith(angles, bead.volume, tilt, wetness, pinning), p.minSlideSpeed);
  bead.speed = target + (bead.speed - target) * std::exp(-p.timeStep / p.speedRelaxationTime);
  const double wanted = bead.arcLength + bead.speed * p.timeStep;
  const double reached = nextDripSite(bead.arcLength, wanted);
  depositTrail(bead, id, reached - bead.arcLength);
  bead.arcLength = reached;
  if (isDripSite(reached)) {
    bead.phase = BeadPhase::Hanging;
    bead.speed = 0.0;
  }
  if (bead.volume < p.minBeadVolume) runOut(bead, id);
}

void LiquidTearSimulation::depositTrail(Bead& bead, int id, double distance) {
  if (!(distance > 0.0)) return;
  const LiquidTearParams& p = input_.params;
  // The width where the bead starts the step holds for all of it (the angles change between pieces).
  const double widthPerCubeRoot = widthPerCubeRoot_[anglesAt(bead.arcLength)];
  // Exact dry consumption over the distance: d(V^(2/3))/ds = -(2/3) h_f c_w.
  const double remaining = std::cbrt(bead.volume) * std::cbrt(bead.volume) -
                           (2.0 / 3.0) * p.filmThickness * widthPerCubeRoot * distance;
  const double dryDeposit = remaining > 0.0 ? bead.volume - remaining * std::sqrt(remaining) : bead.volume;
  const double radius = 0.5 * widthPerCubeRoot * std::cbrt(bead.volume);
  const double width = 2.0 * radius;
  // The film is laid by the rear contact line, a base radius behind the centre.
  const double rear0 = bead.arcLength - radius;
  const double rear1 = rear0 + distance;
  double deposited = 0.0;
  for (size_t cell = cellAt(rear0); cell < cellVolume_.size(); ++cell) {
    const double begin = double(cell) * p.trailCellLength;
    const double end = begin + cellLength(cell);
    if (begin >= rear1) break;
    const double overlap = std::min(end, rear1) - std::max(begin, std::max(rear0, 0.0));
    if (!(overlap > 0.0)) continue;
    const double need = dryDeposit * overlap / distance;
    // Film laid by others is topped up, not doubled; the bead's own film in the cell is not "present".
    const double foreign = cellDepositor_[cell] == id ? cellVolume_[cell] - cellOwnVolume_[cell] : cellVolume_[cell];
    const double present = foreign * overlap / cellLength(cell);
    const double added = std::min(std::max(0.0, need - present), bead.volume - deposited);
    if (added <= 0.0) continue;
    if (cellDepositor_[cell] != id) cellOwnVolume_[cell] = 0.0;
    cellVolume_[cell] += added;
    cellOwnVolume_[cell] += added;
    cellWidth_[cell] = std::max(cellWidth_[cell], width);
    cellDepositor_[cell] = id;
    deposited += added;
  }
  bead.volume -= deposited;
}

void LiquidTearSimulation::runOut(Bead& bead, int id) {
  const double radius = baseRadius(bead.volume, bead.arcLength);
  const size_t cell = cellAt(bead.arcLength - radius);
  cellWidth_[cell] = std::max(cellWidth_[cell], 2.0 * radius);
  if (cellDepositor_[cell] != id) cellOwnVolume_[cell] = 0.0;
  cellVolume_[cell] += bead.volume;
  cellOwnVolume_[cell] += bead.volume;
  cellDepositor_[cell] = id;
  bead.volume = 0.0;
  bead.speed = 0.0;
  bead.phase = BeadPhase::Dried;
}

void LiquidTearSimulation::coalesce() {
  // Beads whose footprints touch (centre gap below the sum of base radii) merge into the one ahead.
  std::vector<int> order;
  for (size_t id = 0; id < beads_.size(); ++id)
    if (isLive(beads_[id])) order.push_back(int(id));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return beads_[a].arcLength < beads_[b].arcLength; });
  for (size_t k = 0; k + 1 < order.size(); ++k) {
    Bead& behind = beads_[order[k]];
    Bead& ahead = beads_[order[k + 1]];
    const double reach = baseRadius(behind.volume, behind.arcLength) + baseRadius(ahead.volume, ahead.arcLength);
    if (ahead.arcLength - behind.arcLength > reach) continue;
    const double volume = ahead.volume + behind.volume;
    if (ahead.phase != BeadPhase::Hanging)
      ahead.speed = (ahead.volume * ahead.speed + behind.volume * behind.speed) / volume;  // momentum kept
    ahead.volume = volume;
    behind.volume = 0.0;
    behind.speed = 0.0;
    behind.phase = BeadPhase::Merged;
    behind.mergedInto = order[k + 1];
  }
}

double LiquidTearSimulation::hangingLimit(double volume, double s) const {
  const double radius =
      input_.params.hangingContactRadius > 0.0 ? input_.params.hangingContactRadius : baseRadius(volume, s);
  return hangingDropMaxVolume(input_.params.fluid, radius);  // Tate 1864
}

void LiquidTearSimulation::detachIfHeavy(Bead& bead, int id) {
  // Tate's limit holds a pendant drop: only under an overhang does it let go. A bead stopped at the
  // path's end on a wall or in a pit pools there (falling, it would pass through the skin below it).
  if (!facesDown(bead.arcLength) || bead.volume <= hangingLimit(bead.volume, bead.arcLength)) return;
  FallingDrop drop;
  drop.beadId = id;
  drop.detachTime = time() + input_.params.timeStep;
  // The drop hangs below its contact point: its centre one sphere radius further along gravity.
  drop.detachCentre = positionAt(bead.arcLength) + gHat_ * equivalentRadius(bead.volume);
  drop.volume = bead.volume;
  drop.oscillation = dropOscillation(input_.params.fluid, input_.params.viscosity, bead.volume, detachAmplitude(bead));
  drops_.push_back(drop);
  detached_ += bead.volume;
  bead.volume = 0.0;
  bead.phase = BeadPhase::Detached;
}

double LiquidTearSimulation::detachAmplitude(const Bead& bead) const {
  const ContactAngleHysteresis& angles = contactAnglesAt(bead.arcLength);
  const double thetaMean = 0.5 * (angles.advancing + angles.receding);
  // The hanging bead as state() reports and the frame draws it (tilt clamped to a wall): long axis
  // along the path's piece, footprint across it, height along the normal.
  const BeadShape shape = beadShape(input_.params.fluid, bead.volume, thetaMean, std::min(tiltAt(bead.arcLength), 0.5 * std::numbers::pi));
  const size_t piece = pieceAt(bead.arcLength);
  const Vec3d normal = input_.path[piece].normal.normalized();
  const Vec3d forward = input_.path[piece + 1].position - input_.path[piece].position;
  const Vec3d along = (forward - forward.dot(normal) * normal).normalized();
  const Vec3d across = normal.cross(along);
  // Half extents of its bounding ellipsoid: halfLength, halfWidth, half the cap's height; the
  // extent of that ellipsoid along gravity (its support sqrt(sum (s_i g_i)^2)) is the released
  // drop's polar semi-axis, its equatorial one keeps the ellipsoid's volume.
  const Vec3d halfExtents(shape.halfLength, shape.halfWidth, 0.5 * shape.height);
  const Vec3d g(gHat_.dot(along), gHat_.dot(across), gHat_.dot(normal));
  const double polar = halfExtents.cwiseProduct(g).norm();
  const double equatorial = std::sqrt(halfExtents.prod() / polar);
  const double amplitude = modeTwoAmplitudeFromAspect(polar / equatorial);
  return std::clamp(amplitude, -kMaxDetachAmplitude, kMaxDetachAmplitude);
}

void LiquidTearSimulation::dryFilm() {
  const LiquidTearParams& p = input_.params;
  const bool exponential = p.filmDryingTime > 0.0;
  const double keep = exponential ? std::exp(-p.timeStep / p.filmDryingTime) : 1.0;
  for (size_t cell = 0; cell < cellVolume_.size(); ++cell) {
    if (!(cellVolume_[cell] > 0.0)) continue;
    // Evaporation: the same volume per length whatever the width (film_evaporation.hpp).
    const double kept = exponential ? cellVolume_[cell] * keep
                                    : std::max(0.0, cellVolume_[cell] - evaporationPerLength_ * cellLength(cell) * p.timeStep);
    dried_ += cellVolume_[cell] - kept;
    cellOwnVolume_[cell] *= kept / cellVolume_[cell];
    cellVolume_[cell] = kept;
  }
}

// ---- Re-routing -----------------------------------------------------------------------------------

void LiquidTearSimulation::reroute(std::vector<LiquidPathSample> path, const std::function<double(double)>& newArcLength) {
  validatePath(path, input_.params.contactAngleRegions.size());
  const double newLength = path.back().arcLength;
  const auto image = [&](double s) {
    const double mapped = newArcLength(s);
    if (!std::isfinite(mapped))
      throw InputError(fmt::format("liquid tear: re-routing maps arc length {} to {}, not a finite length", s, mapped));
    return std::clamp(mapped, 0.0, newLength);
  };
  // Everything is mapped before anything changes, so a throwing map leaves the simulation as it was.
  std::vector<double> beadArcs(beads_.size());
  for (size_t id = 0; id < beads_.size(); ++id)
    beadArcs[id] = beads_[id].arcLength == 0.0 || !isLive(beads_[id]) ? beads_[id].arcLength : image(beads_[id].arcLength);
  rerouteFilm(image, newLength);
  input_.path = std::move(path);
  pathLength_ = newLength;
  if (input_.params.rivulet.formFlowRate > 0.0) tabulateRivuletCells();
  for (size_t id = 0; id < beads_.size(); ++id) {
    Bead& bead = beads_[id];
    if (!isLive(bead)) continue;
    bead.arcLength = beadArcs[id];
    if (bead.phase == BeadPhase::Hanging && !isDripSite(bead.arcLength)) bead.phase = BeadPhase::Pinned;
  }
}

void LiquidTearSimulation::rerouteFilm(const std::function<double(double)>& image, double newLength) {
  const double cellSize = input_.params.trailCellLength;
  const size_t count = std::max<size_t>(size_t(std::ceil(newLength / cellSize)), 1);
  const auto newCell = [&](double s) { return std::min(size_t(std::max(s, 0.0) / cellSize), count - 1); };
  std::vector<double> volume(count, 0.0), width(count, 0.0), own(count, 0.0), largest(count, 0.0);
  std::vector<double> rivulet(count, 0.0), peakFlux(count, 0.0);
  std::vector<int> depositor(count, -1);
  // Each old cell's share of each new cell its image [lo, hi] overlaps (all of it in one cell for an
  // image of zero length, e.g. beyond the new course's end), in proportion to the overlap.
  struct Share {
    size_t from, to;
    double fraction;
  };
  std::vector<Share> shares;
  for (size_t cell = 0; cell < cellVolume_.size(); ++cell) {
    if (!(cellVolume_[cell] > 0.0) && !(rivuletVolume_[cell] > 0.0)) continue;
    const double begin = double(cell) * cellSize;
    const double a = image(begin), b = image(begin + cellLength(cell));
    const double lo = std::min(a, b), hi = std::max(a, b);
    // Overlaps below a billionth of a cell are rounding at a cell's edge (an image ending one ulp
    // into the next cell): they would lay a trace of film, and its wetness, ahead of the trail.
    const size_t first = shares.size();
    double kept = 0.0;
    for (size_t j = newCell(lo); hi > lo && j <= newCell(hi); ++j) {
      const double overlap = std::min(double(j + 1) * cellSize, hi) - std::max(double(j) * cellSize, lo);
      if (!(overlap > 1e-9 * cellSize)) continue;
      shares.push_back({cell, j, overlap});
      kept += overlap;
    }
    if (shares.size() == first) {
      shares.push_back({cell, newCell(0.5 * (lo + hi)), 1.0});
      continue;
    }
    for (size_t k = first; k < shares.size(); ++k) shares[k].fraction /= kept;  // all of the cell's film goes
  }
  // The film keeps the depositor that brought the most of it (what wetnessAhead and depositTrail
  // need to tell a bead's own film from others').
  for (const Share& share : shares) {
    const double added = share.fraction * cellVolume_[share.from];
    rivulet[share.to] += share.fraction * rivuletVolume_[share.from];
    peakFlux[share.to] = std::max(peakFlux[share.to], rivuletPeakFlux_[share.from]);
    volume[share.to] += added;
    width[share.to] = std::max(width[share.to], cellWidth_[share.from]);
    if (added > largest[share.to]) {
      largest[share.to] = added;
      depositor[share.to] = cellDepositor_[share.from];
    }
  }
  for (const Share& share : shares)
    if (depositor[share.to] >= 0 && cellDepositor_[share.from] == depositor[share.to])
      own[share.to] += share.fraction * cellOwnVolume_[share.from];
  cellVolume_ = std::move(volume);
  cellWidth_ = std::move(width);
  cellDepositor_ = std::move(depositor);
  cellOwnVolume_ = std::move(own);
  rivuletVolume_ = std::move(rivulet);
  rivuletPeakFlux_ = std::move(peakFlux);
}

// ---- Output ---------------------------------------------------------------------------------------

VolumeBudget LiquidTearSimulation::budget() const {
  VolumeBudget budget;
  budget.source = sourced_;
  budget.meniscus = meniscus_;
  for (const Bead& bead : beads_) budget.beads += bead.volume;
  budget.film = std::accumulate(cellVolume_.begin(), cellVolume_.end(), 0.0);
  budget.rivulet = std::accumulate(rivuletVolume_.begin(), rivuletVolume_.end(), 0.0);
  budget.detached = detached_;
  budget.dried = dried_;
  return budget;
}

LiquidTearState LiquidTearSimulation::state(double t) const {
  if (stepsFor(t, input_.params.timeStep) != steps_)
    throw InputError(fmt::format("liquid tear: state at {} s asked of a simulation at {} s", t, time()));
  const LiquidTearParams& p = input_.params;
  LiquidTearState state;
  state.time = t;
  state.meniscusVolume = meniscus_;
  for (size_t id = 0; id < beads_.size(); ++id) {
    const Bead& bead = beads_[id];
    if (!isLive(bead)) continue;
    BeadView view;
    view.id = int(id);
    view.phase = bead.phase;
    view.arcLength = bead.arcLength;
    view.speed = bead.speed;
    view.volume = bead.volume;
    view.position = positionAt(bead.arcLength);
    view.normal = input_.path[pieceAt(bead.arcLength)].normal;
    view.tilt = tiltAt(bead.arcLength);
    const ContactAngleHysteresis& angles = contactAnglesAt(bead.arcLength);
    view.contactAngle = 0.5 * (angles.advancing + angles.receding);
    view.shape = beadShape(p.fluid, bead.volume, view.contactAngle, std::min(view.tilt, 0.5 * std::numbers::pi));
    state.beads.push_back(view);
  }
  const Vec3d g = gHat_ * p.fluid.gravity;
  for (const FallingDrop& drop : drops_) {
    const double dt = t - drop.detachTime;  // >= 0: detachments happen at step ends <= time()
    DropView view;
    view.beadId = drop.beadId;
    view.centre = drop.detachCentre + drop.detachVelocity * dt + 0.5 * g * dt * dt;  // ballistic, no drag
    view.velocity = drop.detachVelocity + g * dt;
    view.volume = drop.volume;
    view.radius = equivalentRadius(drop.volume);
    view.axis = view.velocity.squaredNorm() > 0.0 ? view.velocity.normalized() : gHat_;
    view.amplitude = drop.oscillation.amplitudeAt(dt);
    view.amplitudeEnvelope = drop.oscillation.envelopeAt(dt);
    view.axes = modeTwoSpheroid(view.radius, view.amplitude);
    state.drops.push_back(view);
  }
  rivuletViews(state);
  for (const LiquidPathSample& sample : input_.path) state.sampleFilmThickness.push_back(filmThicknessAt(sample.arcLength));
  return state;
}

long long liquidTearStepsTo(double t, double timeStep) { return stepsFor(t, timeStep); }

LiquidTearState simulateLiquidTear(const LiquidTearInput& input, double t) {
  LiquidTearSimulation simulation(input);
  simulation.advanceTo(t);
  return simulation.state(t);
}

VolumeBudget liquidTearVolumeBudget(const LiquidTearInput& input, double t) {
  LiquidTearSimulation simulation(input);
  simulation.advanceTo(t);
  return simulation.budget();
}

}  // namespace lacrima
