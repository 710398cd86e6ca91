// Local subdivision with closure; see region_refinement.hpp.
#include "lacrima/rig/region_refinement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <span>
#include <stdexcept>
#include <utility>

namespace lacrima {

namespace {

constexpr uint32_t kNone = 0xffffffffu;

// The edges of a triangle list, numbered in the order their first corners come, with the
// triangles on each edge (in corner order).
struct EdgeTable {
  std::vector<uint32_t> ofCorner;                  // per corner 3t+k: the edge from corner k to k+1
  std::vector<std::pair<uint32_t, uint32_t>> ends;  // per edge, lower vertex first
  std::vector<uint32_t> triangleStart;             // edge e's triangles: triangleList[triangleStart[e] ..
  std::vector<uint32_t> triangleList;              // .. triangleStart[e + 1]]

  std::span<const uint32_t> trianglesOn(uint32_t edge) const {
    return {triangleList.data() + triangleStart[edge], triangleList.data() + triangleStart[edge + 1]};
  }
};

// With `weld`, vertices at one position count as one (edges are matched geometrically). The
// corners sorted by (edge key, corner) group each edge's corners in corner order; numbering the
// groups by their first corners gives the numbers a scan of the corners would (a hash map per
// corner cost a tenth of a one-frame render of the default shot, in its allocations).
EdgeTable buildEdgeTable(const std::vector<uint32_t>& indices, const std::vector<uint32_t>* weld) {
  const size_t corners = indices.size();
  std::vector<std::pair<uint64_t, uint32_t>> keyed(corners);  // (edge key, corner)
  for (size_t corner = 0; corner < corners; ++corner) {
    const size_t t = corner / 3;
    uint32_t a = indices[corner], b = indices[3 * t + (corner + 1) % 3];
    if (weld) a = (*weld)[a], b = (*weld)[b];
    if (a > b) std::swap(a, b);
    keyed[corner] = {(uint64_t(a) << 32) | b, uint32_t(corner)};
  }
  std::sort(keyed.begin(), keyed.end());
  // Per corner its group (edge in key order); each group's first corner.
  std::vector<uint32_t> groupOf(corners), firstOfGroup;
  for (size_t i = 0; i < corners; ++i) {
    if (i == 0 || keyed[i].first != keyed[i - 1].first) firstOfGroup.push_back(keyed[i].second);
    groupOf[keyed[i].second] = uint32_t(firstOfGroup.size() - 1);
  }
  // Groups numbered as their first corners come.
  std::vector<uint32_t> groupsByFirst(firstOfGroup.size());
  std::iota(groupsByFirst.begin(), groupsByFirst.end(), 0u);
  std::sort(groupsByFirst.begin(), groupsByFirst.end(),
            [&](uint32_t x, uint32_t y) { return firstOfGroup[x] < firstOfGroup[y]; });
  std::vector<uint32_t> edgeOfGroup(firstOfGroup.size());
  for (size_t e = 0; e < groupsByFirst.size(); ++e) edgeOfGroup[groupsByFirst[e]] = uint32_t(e);

  EdgeTable table;
  table.ofCorner.resize(corners);
  for (size_t corner = 0; corner < corners; ++corner) table.ofCorner[corner] = edgeOfGroup[groupOf[corner]];
  table.ends.resize(firstOfGroup.size());
  table.triangleStart.assign(firstOfGroup.size() + 1, 0);
  for (size_t i = 0; i < corners; ++i) {
    const uint32_t e = table.ofCorner[keyed[i].second];
    table.ends[e] = {uint32_t(keyed[i].first >> 32), uint32_t(keyed[i].first)};
    ++table.triangleStart[e + 1];
  }
  for (size_t e = 0; e < firstOfGroup.size(); ++e) table.triangleStart[e + 1] += table.triangleStart[e];
  table.triangleList.resize(corners);
  std::vector<uint32_t> filled(table.triangleStart.begin(), table.triangleStart.end() - 1);
  for (size_t corner = 0; corner < corners; ++corner) table.triangleList[filled[table.ofCorner[corner]]++] = uint32_t(corner / 3);
  return table;
}

// Grows the selection until no unselected triangle has two or more corners on split edges
// (edges of selected triangles); returns which welded edges are split.
std::vector<bool> closeSelection(const EdgeTable& welded, std::vector<bool>& selected) {
  std::vector<bool> split(welded.ends.size(), false);
  const size_t triangleCount = selected.size();
  for (size_t t = 0; t < triangleCount; ++t)
    if (selected[t])
      for (int k = 0; k < 3; ++k) split[welded.ofCorner[3 * t + k]] = true;
  std::vector<uint32_t> work(triangleCount);
  for (size_t t = 0; t < triangleCount; ++t) work[t] = uint32_t(triangleCount - 1 - t);  // pops in order
  while (!work.empty()) {
    const uint32_t t = work.back();
    work.pop_back();
    if (selected[t]) continue;
    int splitCorners = 0;
    for (int k = 0; k < 3; ++k) splitCorners += split[welded.ofCorner[3 * t + k]] ? 1 : 0;
    if (splitCorners < 2) continue;
    selected[t] = true;
    for (int k = 0; k < 3; ++k) {
      const uint32_t e = welded.ofCorner[3 * t + k];
      if (split[e]) continue;
      split[e] = true;
      for (uint32_t other : welded.trianglesOn(e)) work.push_back(other);
    }
  }
  return split;
}

// The corner of triangle t that is neither end of an edge.
uint32_t oppositeCorner(const std::vector<uint32_t>& indices, uint32_t t, std::pair<uint32_t, uint32_t> ends) {
  for (int k = 0; k < 3; ++k) {
    const uint32_t v = indices[3 * t + k];
    if (v != ends.first && v != ends.second) return v;
  }
  return ends.first;  // degenerate triangle; unreachable for the edges that use it
}

// Rows of the old vertices under Loop: the even mask where the whole one-ring is refined and the
// vertex is on no boundary and has no coincident twin; the identity (the vertex stays) otherwise.
class EvenMasks {
 public:
  EvenMasks(const TriangleMesh& mesh, const EdgeTable& raw, const std::vector<uint32_t>& weld,
            const std::vector<bool>& selected) {
    const size_t n = mesh.vertexCount();
    smooth_.assign(n, true);
    neighbours_.resize(n);
    std::vector<uint32_t> groupSize(n, 0), incident(n, 0);
    for (size_t v = 0; v < n; ++v) ++groupSize[weld[v]];
    for (size_t v = 0; v < n; ++v)
      if (groupSize[weld[v]] != 1) smooth_[v] = false;  // a seam copy: stays put like its twin
    for (size_t corner = 0; corner < mesh.indices.size(); ++corner) {
      const uint32_t v = mesh.indices[corner];
      ++incident[v];
      if (!selected[corner / 3]) smooth_[v] = false;
    }
    for (size_t e = 0; e < raw.ends.size(); ++e) {
      const auto [a, b] = raw.ends[e];
      if (a == b) continue;
      neighbours_[a].push_back(b);
      neighbours_[b].push_back(a);
      if (raw.trianglesOn(uint32_t(e)).size() != 2) smooth_[a] = smooth_[b] = false;  // mesh boundary (or non-manifold)
    }
    for (size_t v = 0; v < n; ++v) {
      // A closed fan has as many neighbours as triangles.
      if (incident[v] < 3 || neighbours_[v].size() != incident[v]) smooth_[v] = false;
      std::sort(neighbours_[v].begin(), neighbours_[v].end());
    }
  }

  std::vector<std::pair<uint32_t, float>> row(uint32_t v) const {
    if (!smooth_[v]) return {{v, 1.0f}};
    const size_t valence = neighbours_[v].size();
    // Loop (1987) with Warren's weights: beta = 3/(8n) for n > 3, 3/16 for n = 3.
    const double beta = valence > 3 ? 3.0 / (8.0 * double(valence)) : 3.0 / 16.0;
    std::vector<std::pair<uint32_t, float>> out{{v, float(1.0 - double(valence) * beta)}};
    for (uint32_t u : neighbours_[v]) out.emplace_back(u, float(beta));
    return out;
  }

 private:
  std::vector<bool> smooth_;
  std::vector<std::vector<uint32_t>> neighbours_;
};

// The new vertex of a split raw edge: Loop's odd mask where both triangles are refined and the
// edge has no coincident twin, else the midpoint.
std::vector<std::pair<uint32_t, float>> oddRow(const TriangleMesh& mesh, const EdgeTable& raw, const EdgeTable& welded,
                                               uint32_t rawEdge, uint32_t weldedEdge, const std::vector<bool>& selected,
                                               RefinementScheme scheme) {
  const auto ends = raw.ends[rawEdge];
  const std::span<const uint32_t> sides = raw.trianglesOn(rawEdge);
  const bool interior = sides.size() == 2 && welded.trianglesOn(weldedEdge).size() == 2 && selected[sides[0]] &&
                        selected[sides[1]];
  if (scheme != RefinementScheme::Loop || !interior) return {{ends.first, 0.5f}, {ends.second, 0.5f}};
  return {{ends.first, 0.375f},
          {ends.second, 0.375f},
          {oppositeCorner(mesh.indices, sides[0], ends), 0.125f},
          {oppositeCorner(mesh.indices, sides[1], ends), 0.125f}};
}

void appendTriangle(RegionRefinement& out, uint32_t a, uint32_t b, uint32_t c, bool refined) {
  out.indices.insert(out.indices.end(), {a, b, c});
  out.refined.push_back(refined);
}

// Each triangle in order: refined 1-to-4, split in two on its one split edge, or copied.
void buildTriangles(const TriangleMesh& mesh, const EdgeTable& raw, const std::vector<uint32_t>& edgeVertex,
                    const std::vector<bool>& selected, RegionRefinement& out) {
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    uint32_t m[3];
    for (int k = 0; k < 3; ++k) m[k] = edgeVertex[raw.ofCorner[3 * t + k]];
    if (selected[t]) {
      appendTriangle(out, v[0], m[0], m[2], true);
      appendTriangle(out, m[0], v[1], m[1], true);
      appendTriangle(out, m[2], m[1], v[2], true);
      appendTriangle(out, m[0], m[1], m[2], true);
      continue;
    }
    int k = 0;
    while (k < 3 && m[k] == kNone) ++k;
    if (k == 3) {
      appendTriangle(out, v[0], v[1], v[2], false);
      continue;
    }
    // Edge v[k] -> v[k+1] is split at m[k]; fan from the opposite corner keeps the winding.
    const uint32_t a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
    appendTriangle(out, a, m[k], c, false);
    appendTriangle(out, m[k], b, c, false);
  }
}

template <typename V>
std::vector<V> applyRows(const VertexStencils& stencils, const std::vector<V>& values) {
  for (uint32_t s : stencils.sources)
    if (s >= values.size()) throw std::invalid_argument("applyStencils: stencil source out of range");
  std::vector<V> out(stencils.size());
  for (size_t r = 0; r < stencils.size(); ++r) {
    const uint32_t begin = stencils.offsets[r], end = stencils.offsets[r + 1];
    if (end - begin == 1 && stencils.weights[begin] == 1.0f) {
      out[r] = values[stencils.sources[begin]];  // bitwise copy
      continue;
    }
    V sum = V::Zero();
    for (uint32_t k = begin; k < end; ++k) sum += stencils.weights[k] * values[stencils.sources[k]];
    out[r] = sum;
  }
  return out;
}

bool isIdentityRow(const VertexStencils& stencils, size_t r) {
  const uint32_t begin = stencils.offsets[r];
  return stencils.offsets[r + 1] - begin == 1 && stencils.weights[begin] == 1.0f;
}

// The 4 largest joint influences of a combination of skinned vertices, normalised.
void combineInfluences(const std::vector<std::pair<uint16_t, double>>& terms, std::array<uint16_t, 4>& joints,
                       Vec4& weights) {
  std::vector<std::pair<uint16_t, double>> perJoint;
  for (const auto& [joint, w] : terms) {
    // Copied into the lambda: clang 14 (tools/hardening.sh) cannot capture a structured binding.
    auto it = std::find_if(perJoint.begin(), perJoint.end(), [j = joint](const auto& p) { return p.first == j; });
    if (it == perJoint.end()) perJoint.emplace_back(joint, w);
    else it->second += w;
  }
  std::sort(perJoint.begin(), perJoint.end(),
            [](const auto& x, const auto& y) { return x.second != y.second ? x.second > y.second : x.first < y.first; });
  if (perJoint.size() > 4) perJoint.resize(4);
  double sum = 0.0;
  for (const auto& p : perJoint) sum += p.second;
  joints.fill(0);
  weights = Vec4::Zero();
  for (size_t c = 0; c < perJoint.size(); ++c) {
    joints[c] = perJoint[c].first;
    weights[int(c)] = sum > 0.0 ? float(perJoint[c].second / sum) : (c == 0 ? 1.0f : 0.0f);
  }
}

void checkLevels(int levels, const char* what) {
  if (levels < 0) throw std::invalid_argument(std::string(what) + ": levels must not be negative");
}

void checkSelection(const TriangleMesh& mesh, const std::vector<bool>& selected) {
  if (selected.size() != mesh.triangleCount())
    throw std::invalid_argument("refineRegionOnce: the selection needs one entry per triangle");
}

}  // namespace

void VertexStencils::add(const std::vector<std::pair<uint32_t, float>>& row) {
  for (const auto& [source, weight] : row) {
    sources.push_back(source);
    weights.push_back(weight);
  }
  offsets.push_back(uint32_t(sources.size()));
}

RegionRefinement refineRegionOnce(const TriangleMesh& mesh, const std::vector<bool>& selection,
                                  RefinementScheme scheme) {
  checkSelection(mesh, selection);
  std::vector<bool> selected = selection;
  const std::vector<uint32_t> weld = findCoincidentVertices(mesh);
  const EdgeTable welded = buildEdgeTable(mesh.indices, &weld);
  const EdgeTable raw = buildEdgeTable(mesh.indices, nullptr);
  const std::vector<bool> split = closeSelection(welded, selected);

  RegionRefinement out;
  out.refinedParents = size_t(std::count(selected.begin(), selected.end(), true));
  if (scheme == RefinementScheme::Loop) {
    const EvenMasks even(mesh, raw, weld, selected);
    for (uint32_t v = 0; v < mesh.vertexCount(); ++v) out.stencils.add(even.row(v));
  } else {
    for (uint32_t v = 0; v < mesh.vertexCount(); ++v) out.stencils.add({{v, 1.0f}});
  }

  // One new vertex per split raw edge; a seam edge's twin gets its own (same position, own uv).
  std::vector<uint32_t> weldedOfRaw(raw.ends.size(), kNone);
  for (size_t corner = 0; corner < mesh.indices.size(); ++corner) weldedOfRaw[raw.ofCorner[corner]] = welded.ofCorner[corner];
  std::vector<uint32_t> edgeVertex(raw.ends.size(), kNone);
  for (uint32_t e = 0; e < raw.ends.size(); ++e) {
    if (!split[weldedOfRaw[e]]) continue;
    edgeVertex[e] = uint32_t(out.stencils.size());
    out.stencils.add(oddRow(mesh, raw, welded, e, weldedOfRaw[e], selected, scheme));
  }
  buildTriangles(mesh, raw, edgeVertex, selected, out);
  return out;
}

std::vector<Vec3> applyStencils(const VertexStencils& stencils, const std::vector<Vec3>& values) {
  return applyRows(stencils, values);
}

std::vector<Vec2> applyStencils(const VertexStencils& stencils, const std::vector<Vec2>& values) {
  return applyRows(stencils, values);
}

SparseDelta applyStencils(const VertexStencils& stencils, const SparseDelta& delta, size_t oldVertexCount) {
  std::vector<Vec3> dense(oldVertexCount, Vec3::Zero());
  std::vector<bool> moved(oldVertexCount, false);
  for (size_t i = 0; i < delta.vertices.size(); ++i) {
    if (delta.vertices[i] >= oldVertexCount) throw std::invalid_argument("applyStencils: delta vertex out of range");
    dense[delta.vertices[i]] = delta.deltas[i];
    moved[delta.vertices[i]] = true;
  }
  SparseDelta out;
  for (size_t r = 0; r < stencils.size(); ++r) {
    const uint32_t begin = stencils.offsets[r], end = stencils.offsets[r + 1];
    bool any = false;
    for (uint32_t k = begin; k < end && !any; ++k) any = moved.at(stencils.sources[k]);
    if (!any) continue;
    Vec3 sum = Vec3::Zero();
    if (isIdentityRow(stencils, r)) sum = dense[stencils.sources[begin]];
    else
      for (uint32_t k = begin; k < end; ++k) sum += stencils.weights[k] * dense[stencils.sources[k]];
    if (sum == Vec3::Zero()) continue;
    out.vertices.push_back(uint32_t(r));
    out.deltas.push_back(sum);
  }
  return out;
}

void applyStencils(const VertexStencils& stencils, std::vector<std::array<uint16_t, 4>>& joints,
                   std::vector<Vec4>& weights) {
  if (joints.size() != weights.size()) throw std::invalid_argument("applyStencils: joints and weights differ in size");
  std::vector<std::array<uint16_t, 4>> newJoints(stencils.size());
  std::vector<Vec4> newWeights(stencils.size());
  std::vector<std::pair<uint16_t, double>> terms;
  for (size_t r = 0; r < stencils.size(); ++r) {
    const uint32_t begin = stencils.offsets[r], end = stencils.offsets[r + 1];
    if (isIdentityRow(stencils, r)) {
      newJoints[r] = joints.at(stencils.sources[begin]);
      newWeights[r] = weights[stencils.sources[begin]];
      continue;
    }
    terms.clear();
    for (uint32_t k = begin; k < end; ++k) {
      const uint32_t s = stencils.sources[k];
      for (int c = 0; c < 4; ++c)
        if (weights.at(s)[c] != 0.0f) terms.emplace_back(joints[s][size_t(c)], double(stencils.weights[k]) * weights[s][c]);
    }
    combineInfluences(terms, newJoints[r], newWeights[r]);
  }
  joints = std::move(newJoints);
  weights = std::move(newWeights);
}

TriangleMesh refineMesh(const TriangleMesh& mesh, std::vector<bool> selected, RefinementScheme scheme, int levels) {
  checkLevels(levels, "refineMesh");
  checkSelection(mesh, selected);
  TriangleMesh out = mesh;
  if (levels == 0 || std::none_of(selected.begin(), selected.end(), [](bool s) { return s; })) return out;
  for (int level = 0; level < levels; ++level) {
    RegionRefinement r = refineRegionOnce(out, selected, scheme);
    out.positions = applyStencils(r.stencils, out.positions);
    if (!out.uvs.empty()) out.uvs = applyStencils(r.stencils, out.uvs);
    out.indices = std::move(r.indices);
    selected = std::move(r.refined);
  }
  if (!mesh.normals.empty()) computeSmoothNormals(out);
  return out;
}

namespace {

// Per vertex, the original vertices (with weights) whose normals its normal blends; empty: its own.
using NormalSourceRows = std::vector<std::vector<std::pair<uint32_t, float>>>;

NormalSourceRows rowsOf(const VertexStencils& stencils, size_t vertexCount) {
  NormalSourceRows rows(vertexCount);
  if (stencils.size() != vertexCount) return rows;  // none recorded (or from another mesh): own normals
  for (size_t v = 0; v < vertexCount; ++v)
    for (uint32_t k = stencils.offsets[v]; k < stencils.offsets[v + 1]; ++k)
      rows[v].emplace_back(stencils.sources[k], stencils.weights[k]);
  return rows;
}

VertexStencils stencilsOf(const NormalSourceRows& rows) {
  VertexStencils stencils;
  if (std::all_of(rows.begin(), rows.end(), [](const auto& row) { return row.empty(); })) return stencils;
  for (const auto& row : rows) stencils.add(row);
  return stencils;
}

// The rows of the refined vertices: each stencil source replaced by its own row (when it has one),
// weights multiplied, duplicates summed. A vertex that is just one source with its own normal
// (an original vertex) gets an empty row.
NormalSourceRows composeNormalSources(const VertexStencils& stencils, const NormalSourceRows& previous) {
  NormalSourceRows rows(stencils.size());
  for (size_t v = 0; v < stencils.size(); ++v) {
    std::vector<std::pair<uint32_t, float>>& row = rows[v];
    auto addSource = [&row](uint32_t source, float weight) {
      for (auto& [existing, w] : row)
        if (existing == source) {
          w += weight;
          return;
        }
      row.emplace_back(source, weight);
    };
    for (uint32_t k = stencils.offsets[v]; k < stencils.offsets[v + 1]; ++k) {
      const uint32_t source = stencils.sources[k];
      const float weight = stencils.weights[k];
      if (previous[source].empty()) addSource(source, weight);
      else
        for (const auto& [original, w] : previous[source]) addSource(original, weight * w);
    }
    if (row.size() == 1 && row.front().first == v) row.clear();  // an original vertex kept in place
  }
  return rows;
}

}  // namespace

GltfPrimitive refinePrimitive(const GltfPrimitive& primitive, std::vector<bool> selected, RefinementScheme scheme,
                              int levels, std::vector<Vec3>* carried) {
  checkLevels(levels, "refinePrimitive");
  checkSelection(primitive.mesh, selected);
  if (carried && carried->size() != primitive.mesh.vertexCount())
    throw std::invalid_argument(fmt::format("refinePrimitive: {} carried values for {} vertices", carried->size(),
                                            primitive.mesh.vertexCount()));
  GltfPrimitive out = primitive;
  if (levels == 0 || std::none_of(selected.begin(), selected.end(), [](bool s) { return s; })) return out;
  TriangleMesh& mesh = out.mesh;
  NormalSourceRows normalRows = rowsOf(out.normalSources, mesh.vertexCount());
  if (scheme == RefinementScheme::Linear && out.normalTriangles.empty()) out.normalTriangles = mesh.indices;
  for (int level = 0; level < levels; ++level) {
    RegionRefinement r = refineRegionOnce(mesh, selected, scheme);
    const size_t oldCount = mesh.vertexCount();
    if (scheme == RefinementScheme::Linear) normalRows = composeNormalSources(r.stencils, normalRows);
    mesh.positions = applyStencils(r.stencils, mesh.positions);
    if (!mesh.uvs.empty()) mesh.uvs = applyStencils(r.stencils, mesh.uvs);
    for (SparseDelta& target : out.targets) target = applyStencils(r.stencils, target, oldCount);
    if (!out.skinJoints.empty()) applyStencils(r.stencils, out.skinJoints, out.skinWeights);
    if (carried) *carried = applyStencils(r.stencils, *carried);
    mesh.indices = std::move(r.indices);
    selected = std::move(r.refined);
  }
  if (scheme == RefinementScheme::Linear) {
    out.normalSources = stencilsOf(normalRows);
  } else {
    out.normalTriangles.clear();
    out.normalSources = VertexStencils();
  }
  // As the loader does for every primitive: welded by position, smooth, area-weighted.
  out.weldMap = findCoincidentVertices(mesh);
  computePrimitiveNormals(mesh, out);
  return out;
}

void computePrimitiveNormals(TriangleMesh& mesh, const GltfPrimitive& primitive) {
  // The primitive's own map, not a copy (the rig calls this every frame); built only when missing.
  std::vector<uint32_t> builtWeldMap;
  if (primitive.weldMap.size() != mesh.vertexCount()) builtWeldMap = findCoincidentVertices(primitive.mesh);
  const std::vector<uint32_t>& weldMap = builtWeldMap.empty() ? primitive.weldMap : builtWeldMap;
  if (primitive.normalTriangles.empty()) {
    computeSmoothNormals(mesh, weldMap);
    return;
  }
  const VertexStencils& normalSources = primitive.normalSources;
  if (normalSources.size() != mesh.vertexCount())
    throw std::invalid_argument(fmt::format("computePrimitiveNormals: primitive '{}': {} normal rows for {} vertices",
                                            primitive.name, normalSources.size(), mesh.vertexCount()));
  // The original vertices as the unrefined mesh shades them (added vertices lie on no triangle
  // of it and get a placeholder, replaced below).
  std::vector<uint32_t> refinedTriangles = std::move(mesh.indices);
  mesh.indices = primitive.normalTriangles;
  computeSmoothNormals(mesh, weldMap);
  mesh.indices = std::move(refinedTriangles);
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const uint32_t begin = normalSources.offsets[v], end = normalSources.offsets[v + 1];
    if (begin == end) continue;
    Vec3 blend = Vec3::Zero();
    for (uint32_t k = begin; k < end; ++k) blend += normalSources.weights[k] * mesh.normals[normalSources.sources[k]];
    // Opposite normals cancel only across a fold; there any of them will do.
    mesh.normals[v] = blend.squaredNorm() > 1e-12f ? blend.normalized() : mesh.normals[normalSources.sources[begin]];
  }
}

}  // namespace lacrima
