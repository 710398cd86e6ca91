// The rivulet of a liquid tear: LiquidTearSimulation's cells carrying a continuous stream; see
// "Rivulets" in liquid_tear.hpp and the flow law in rivulet.hpp.
#include <algorithm>
#include <cmath>

#include "lacrima/liquid/liquid_tear.hpp"

namespace lacrima {

namespace {
// The largest Courant number 2 k A dt / cell of a sub-step: first-order upwind is monotone up to 1.
constexpr double kMaxCourant = 0.5;
// Narrower stretches (a film's worth of liquid left after the rivulet broke up) are not drawn.
constexpr double kMinDrawnHalfWidth = 1e-5;  // m
}  // namespace

bool LiquidTearSimulation::wellsAsRivulet() const {
  const LiquidTearParams& p = input_.params;
  return p.rivulet.formFlowRate > 0.0 && p.source.rateAt(time()) >= p.rivulet.formFlowRate;
}

RivuletFlow LiquidTearSimulation::rivuletFlowAt(double s) const {
  RivuletFlow flow;
  flow.fluid = input_.params.fluid;
  flow.viscosity = input_.params.viscosity;
  flow.contactAngle = contactAnglesAt(s).receding;
  flow.slope = tiltAt(s);
  return flow;
}

void LiquidTearSimulation::tabulateRivuletCells() {
  const size_t cells = rivuletVolume_.size();
  cellFlow_.resize(cells);
  cellFluxCoefficient_.resize(cells);
  for (size_t cell = 0; cell < cells; ++cell) {
    cellFlow_[cell] = rivuletFlowAt((double(cell) + 0.5) * input_.params.trailCellLength);
    cellFluxCoefficient_[cell] = rivuletFluxCoefficient(cellFlow_[cell]);
  }
}

double LiquidTearSimulation::dripSiteOfRivulet() const { return nextDripSite(0.0, pathLength_); }

size_t LiquidTearSimulation::rivuletCellEnd() const {
  const double drip = dripSiteOfRivulet();
  const double cells = std::ceil(drip / input_.params.trailCellLength);
  return std::clamp(size_t(cells), size_t(1), rivuletVolume_.size());
}

void LiquidTearSimulation::feedDripSite(double volume) {
  if (!(volume > 0.0)) return;
  const double drip = dripSiteOfRivulet();
  for (size_t id = 0; id < beads_.size(); ++id) {
    Bead& bead = beads_[id];
    if (bead.phase == BeadPhase::Hanging && std::abs(bead.arcLength - drip) <= baseRadius(bead.volume, drip)) {
      bead.volume += volume;
      return;
    }
  }
  beads_.push_back(Bead{drip, 0.0, volume, BeadPhase::Hanging, time() + input_.params.timeStep, -1});
}

void LiquidTearSimulation::flowRivulet() {
  const size_t end = rivuletCellEnd();
  // Liquid below the first drip site (the course moved under it) runs straight on to it.
  double toDrip = 0.0;
  for (size_t cell = end; cell < rivuletVolume_.size(); ++cell) {
    toDrip += rivuletVolume_[cell];
    rivuletVolume_[cell] = 0.0;
    rivuletPeakFlux_[cell] = 0.0;
  }
  size_t last = 0;  // one past the lowest cell holding liquid
  for (size_t cell = 0; cell < end; ++cell)
    if (rivuletVolume_[cell] > 0.0) last = cell + 1;
  if (last == 0) {
    feedDripSite(toDrip);
    return;
  }
  // Q = k A^2 per cell at its centre's slope and angle; the sub-step keeps 2 k A dt / length <= kMaxCourant.
  const size_t reach = std::min(end, last + 1);
  std::vector<double> k(reach), length(reach);
  double courant = 0.0;
  for (size_t cell = 0; cell < reach; ++cell) {
    length[cell] = cellLength(cell);
    k[cell] = cellFluxCoefficient_[cell];
    const double area = rivuletVolume_[cell] / length[cell];
    courant = std::max(courant, 2.0 * k[cell] * area * input_.params.timeStep / length[cell]);
  }
  const int substeps = std::max(1, int(std::ceil(courant / kMaxCourant)));
  const double dt = input_.params.timeStep / double(substeps);
  std::vector<double> outflow(reach);
  for (int sub = 0; sub < substeps; ++sub) {
    for (size_t cell = 0; cell < reach; ++cell) {
      const double area = rivuletVolume_[cell] / length[cell];
      outflow[cell] = std::min(rivuletVolume_[cell], k[cell] * area * area * dt);
    }
    for (size_t cell = 0; cell < reach; ++cell) {
      rivuletVolume_[cell] -= outflow[cell];
      if (cell + 1 < end)
        rivuletVolume_[cell + 1] += outflow[cell];
      else
        toDrip += outflow[cell];
    }
  }
  for (size_t cell = 0; cell < reach; ++cell) {
    const double area = rivuletVolume_[cell] / length[cell];
    rivuletPeakFlux_[cell] = rivuletVolume_[cell] > 0.0 ? std::max(rivuletPeakFlux_[cell], k[cell] * area * area) : 0.0;
  }
  feedDripSite(toDrip);
}

void LiquidTearSimulation::wetUnderRivulet() {
  const LiquidTearParams& p = input_.params;
  for (size_t cell = 0; cell < rivuletVolume_.size(); ++cell) {
    if (!(rivuletVolume_[cell] > 0.0)) continue;
    const double length = cellLength(cell);
    const double width = 2.0 * rivuletHalfWidth(cellFlow_[cell], rivuletVolume_[cell] / length);
    const double wanted = p.filmThickness * std::max(width, cellWidth_[cell]) * length;
    const double added = std::min(std::max(0.0, wanted - cellVolume_[cell]), rivuletVolume_[cell]);
    cellWidth_[cell] = std::max(cellWidth_[cell], width);
    if (!(added > 0.0)) continue;
    rivuletVolume_[cell] -= added;
    cellVolume_[cell] += added;
    if (cellDepositor_[cell] >= 0) cellOwnVolume_[cell] = 0.0;
    cellDepositor_[cell] = -1;  // laid by the rivulet: every bead's foreign film
  }
}

void LiquidTearSimulation::joinRivulet() {
  const size_t end = rivuletCellEnd();
  for (Bead& bead : beads_) {
    if (!isLiveBeadPhase(bead.phase) || bead.phase == BeadPhase::Hanging) continue;
    const size_t cell = cellAt(bead.arcLength);
    if (cell >= end || !(rivuletVolume_[cell] > 0.0)) continue;
    rivuletVolume_[cell] += bead.volume;
    bead.volume = 0.0;
    bead.speed = 0.0;
    bead.phase = BeadPhase::InRivulet;
  }
}

void LiquidTearSimulation::breakRivulet() {
  // From the top down: cells that once carried the break flow rate and now carry less gather into
  // stretches of one break-up spacing; a stretch breaks when it is that long or reaches the rivulet's
  // lower end (a shorter stretch above flowing rivulet waits: it is still draining into it).
  const double cellSize = input_.params.trailCellLength;
  const size_t end = rivuletCellEnd();
  auto breaking = [&](size_t cell) {
    if (!(rivuletVolume_[cell] > 0.0) || !(rivuletPeakFlux_[cell] >= breakFlowRate_)) return false;
    const double area = rivuletVolume_[cell] / cellLength(cell);
    return cellFluxCoefficient_[cell] * area * area < breakFlowRate_;
  };
  size_t cell = 0;
  while (cell < end) {
    if (!breaking(cell)) {
      ++cell;
      continue;
    }
    const size_t first = cell;
    size_t last = cell;
    double widest = 0.0;
    bool longEnough = false;
    for (; last < end && breaking(last); ++last) {
      const RivuletFlow& flow = cellFlow_[last];
      widest = std::max(widest, rivuletHalfWidthForFlux(flow, rivuletPeakFlux_[last]));
      longEnough = double(last + 1 - first) * cellSize >= rivuletBreakupSpacing(flow, widest);
      if (longEnough) break;
    }
    if (!longEnough) --last;  // the loop stopped one past the stretch
    const bool rivuletEndsBelow = last + 1 >= end || !(rivuletVolume_[last + 1] > 0.0);
    if (longEnough || rivuletEndsBelow) breakStretch(first, last, widest);
    cell = last + 1;
  }
}

void LiquidTearSimulation::breakStretch(size_t first, size_t last, double halfWidth) {
  const LiquidTearParams& p = input_.params;
  double volume = 0.0, moment = 0.0;
  for (size_t cell = first; cell <= last; ++cell) {
    const double centre = double(cell) * p.trailCellLength + 0.5 * cellLength(cell);
    volume += rivuletVolume_[cell];
    moment += rivuletVolume_[cell] * centre;
    rivuletVolume_[cell] = 0.0;
    rivuletPeakFlux_[cell] = 0.0;
  }
  if (!(volume > 0.0)) return;
  const double at = std::clamp(moment / volume, 0.0, pathLength_);
  if (volume >= p.minBeadVolume) {
    beads_.push_back(Bead{at, 0.0, volume, BeadPhase::Pinned, time() + p.timeStep, -1});
    return;
  }
  // Too little for a bead: it stays as film where the stretch was.
  const size_t cell = cellAt(at);
  cellWidth_[cell] = std::max(cellWidth_[cell], 2.0 * halfWidth);
  cellVolume_[cell] += volume;
  if (cellDepositor_[cell] >= 0) cellOwnVolume_[cell] = 0.0;
  cellDepositor_[cell] = -1;
}

void LiquidTearSimulation::rivuletViews(LiquidTearState& state) const {
  if (!(input_.params.rivulet.formFlowRate > 0.0)) return;  // no rivulet, and no flow law tabulated
  const double cellSize = input_.params.trailCellLength;
  RivuletView run;
  auto close = [&] {
    if (!run.stations.empty()) state.rivulets.push_back(run);
    run = RivuletView{};
  };
  for (size_t cell = 0; cell < rivuletVolume_.size(); ++cell) {
    const double length = cellLength(cell);
    const double s = double(cell) * cellSize + 0.5 * length;
    const double halfWidth = rivuletVolume_[cell] > 0.0 ? rivuletHalfWidth(cellFlow_[cell], rivuletVolume_[cell] / length) : 0.0;
    if (halfWidth < kMinDrawnHalfWidth) {
      close();
      continue;
    }
    if (run.stations.empty()) run.begin = double(cell) * cellSize;
    run.end = double(cell) * cellSize + length;
    run.volume += rivuletVolume_[cell];
    run.stations.push_back(
        RivuletStation{s, positionAt(s), input_.path[pieceAt(s)].normal, halfWidth, rivuletHeight(cellFlow_[cell], halfWidth)});
  }
  close();
}

}  // namespace lacrima
