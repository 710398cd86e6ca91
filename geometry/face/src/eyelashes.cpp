// Eyelashes as tubes on lash-card strips; see eyelashes.hpp.
#include "lacrima/face/eyelashes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "lacrima/base/error.hpp"
#include "lacrima/base/hash.hpp"

namespace lacrima {

namespace {

// Connected pieces of the mesh (union-find over triangles), each a sorted vertex list.
std::vector<std::vector<uint32_t>> connectedPieces(const TriangleMesh& mesh) {
  std::vector<uint32_t> parent(mesh.vertexCount());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const uint32_t a = find(mesh.indices[i]);
    parent[find(mesh.indices[i + 1])] = a;
    parent[find(mesh.indices[i + 2])] = a;
  }
  std::map<uint32_t, std::vector<uint32_t>> pieces;
  for (uint32_t v = 0; v < mesh.vertexCount(); ++v) pieces[find(v)].push_back(v);
  std::vector<std::vector<uint32_t>> out;
  for (auto& [root, vertices] : pieces) out.push_back(std::move(vertices));
  return out;
}

// Texture coordinates of one grid line agree to within this (the ICT cards' differ by ~1e-4;
// their lines are ~0.03 apart).
constexpr float kGridLineTolerance = 2e-3f;

// One value per grid line, ascending: values closer than the tolerance to the previous are the same line.
std::vector<float> distinctValues(std::vector<float> values) {
  std::sort(values.begin(), values.end());
  std::vector<float> out;
  for (float x : values)
    if (out.empty() || x - out.back() > kGridLineTolerance) out.push_back(x);
  return out;
}

// The grid line of a value: the last line at or below it (within the tolerance).
int indexOf(const std::vector<float>& lines, float x) {
  const auto it = std::upper_bound(lines.begin(), lines.end(), x + kGridLineTolerance);
  return int(it - lines.begin()) - 1;
}

LashStrip gridOf(const TriangleMesh& cards, const std::vector<uint32_t>& piece, const Vec3& eyeCenter,
                 const std::string& what, size_t pieceIndex) {
  std::vector<float> us, vs;
  for (uint32_t v : piece) {
    us.push_back(cards.uvs[v].x());
    vs.push_back(cards.uvs[v].y());
  }
  const std::vector<float> columns = distinctValues(us), rows = distinctValues(vs);
  LashStrip strip;
  strip.columns = int(columns.size());
  strip.rows = int(rows.size());
  const std::string notGrid = fmt::format(
      "{}: lash strip {} ({} vertices) is not a grid of columns along the lid by rows from root to tip in its "
      "texture coordinates",
      what, pieceIndex, piece.size());
  if (strip.columns < 2 || strip.rows < 2 || size_t(strip.columns * strip.rows) != piece.size())
    throw InputError(notGrid);
  strip.vertices.assign(piece.size(), UINT32_MAX);
  for (uint32_t v : piece) {
    uint32_t& slot = strip.vertices[size_t(indexOf(rows, cards.uvs[v].y()) * strip.columns +
                                           indexOf(columns, cards.uvs[v].x()))];
    if (slot != UINT32_MAX) throw InputError(notGrid);
    slot = v;
    strip.restCentroid += cards.positions[v] / float(piece.size());
  }
  // Row 0 must be the root: the end row nearer to the eye.
  auto rowDistance = [&](int row) {
    float d = 0.0f;
    for (int c = 0; c < strip.columns; ++c)
      d += (cards.positions[strip.vertices[size_t(row * strip.columns + c)]] - eyeCenter).norm();
    return d;
  };
  if (rowDistance(strip.rows - 1) < rowDistance(0)) {
    std::vector<uint32_t> flipped;
    for (int r = strip.rows - 1; r >= 0; --r)
      flipped.insert(flipped.end(), strip.vertices.begin() + r * strip.columns,
                     strip.vertices.begin() + (r + 1) * strip.columns);
    strip.vertices = std::move(flipped);
  }
  return strip;
}

float random01(uint64_t seed, uint64_t lash, uint64_t dimension) {
  return uint64ToUnitFloat(hashCombine(hashCombine(mix64(seed), lash), dimension));
}

}  // namespace

std::vector<LashStrip> findLashStrips(const TriangleMesh& cards, const Vec3& eyeCenter, const std::string& what) {
  if (cards.uvs.size() != cards.positions.size() || cards.positions.empty())
    throw InputError(fmt::format("{}: the lash cards need texture coordinates to find their strips", what));
  std::vector<LashStrip> strips;
  const auto pieces = connectedPieces(cards);
  for (size_t i = 0; i < pieces.size(); ++i) strips.push_back(gridOf(cards, pieces[i], eyeCenter, what, i));
  return strips;
}

std::vector<Lash> placeLashes(const std::vector<LashStrip>& strips, const Vec3& eyeCenter, const Vec3& up, float reach,
                              const LashParams& params) {
  std::vector<Lash> lashes;
  for (const bool upper : {true, false}) {
    std::vector<uint32_t> lid;
    for (uint32_t s = 0; s < strips.size(); ++s) {
      const Vec3 d = strips[s].restCentroid - eyeCenter;
      if (d.norm() <= reach && (d.dot(up) > 0.0f) == upper) lid.push_back(s);
    }
    const int count = upper ? params.upper : params.lower;
    if (lid.empty() || count == 0) continue;
    for (int i = 0; i < count; ++i) {
      const uint64_t key = uint64_t(lashes.size());
      Lash lash;
      lash.upper = upper;
      lash.strip = lid[size_t(random01(params.seed, key, 0) * float(lid.size())) % lid.size()];
      // Evenly along the lid, each lash jittered within its slot (no clumps, no gaps).
      const float along = (float(i) + 0.1f + 0.8f * random01(params.seed, key, 1)) / float(count);
      lash.column = along * float(strips[lash.strip].columns - 1);
      lash.lengthFactor = params.minLength + (1.0f - params.minLength) * random01(params.seed, key, 2);
      lash.drift = params.spread * (2.0f * random01(params.seed, key, 3) - 1.0f);
      lashes.push_back(lash);
    }
  }
  return lashes;
}

std::vector<Vec3> lashCentreline(const LashStrip& strip, const Lash& lash, const TriangleMesh& posed) {
  const int c0 = std::clamp(int(std::floor(lash.column)), 0, strip.columns - 2);
  const float f = lash.column - float(c0);
  auto at = [&](int row, int column) { return posed.positions[strip.vertices[size_t(row * strip.columns + column)]]; };
  std::vector<Vec3> line;
  for (int r = 0; r < strip.rows; ++r) line.push_back((1.0f - f) * at(r, c0) + f * at(r, c0 + 1));
  const Vec3 alongLid = (at(0, c0 + 1) - at(0, c0)).normalized();
  const Vec3 root = line.front();
  for (int r = 0; r < strip.rows; ++r) {
    const float s = float(r) / float(strip.rows - 1);
    // Shortened towards the root; the drift grows quadratically so the root stays on the lid.
    line[size_t(r)] = root + lash.lengthFactor * (line[size_t(r)] - root) + s * s * lash.drift * alongLid;
  }
  return line;
}

namespace {

// A closed tube around the centreline, radius tapering linearly from root to tip, capped at both ends.
void appendTube(TriangleMesh& mesh, const std::vector<Vec3>& line, const LashParams& params) {
  const uint32_t base = uint32_t(mesh.positions.size()), n = uint32_t(params.sides);
  const size_t rings = line.size();
  Vec3 reference = Vec3::UnitY();
  for (size_t r = 0; r < rings; ++r) {
    const Vec3 tangent =
        (line[std::min(r + 1, rings - 1)] - line[r > 0 ? r - 1 : 0]).normalized();
    if (std::abs(tangent.dot(reference)) > 0.9f) reference = Vec3::UnitX();
    const Vec3 u = (reference - reference.dot(tangent) * tangent).normalized(), v = tangent.cross(u);
    reference = u;  // carried along: no twist between rings
    const float s = float(r) / float(rings - 1);
    const float radius = params.rootRadius + s * (params.tipRadius - params.rootRadius);
    for (uint32_t k = 0; k < n; ++k) {
      const float phi = 2.0f * kPi * float(k) / float(n);
      const Vec3 out = std::cos(phi) * u + std::sin(phi) * v;
      mesh.positions.push_back(line[r] + radius * out);
      mesh.normals.push_back(out);
    }
  }
  for (uint32_t r = 0; r + 1 < rings; ++r)
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t a = base + r * n + k, b = base + r * n + (k + 1) % n, c = a + n, d = b + n;
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
    }
  const uint32_t rootCap = uint32_t(mesh.positions.size()), tipCap = rootCap + 1, last = base + uint32_t(rings - 1) * n;
  mesh.positions.push_back(line.front());
  mesh.normals.push_back((line.front() - line[1]).normalized());
  mesh.positions.push_back(line.back());
  mesh.normals.push_back((line.back() - line[rings - 2]).normalized());
  for (uint32_t k = 0; k < n; ++k) {
    mesh.indices.insert(mesh.indices.end(), {base + (k + 1) % n, base + k, rootCap});
    mesh.indices.insert(mesh.indices.end(), {last + k, last + (k + 1) % n, tipCap});
  }
}

}  // namespace

TriangleMesh buildLashes(const std::vector<LashStrip>& strips, const std::vector<Lash>& lashes,
                         const TriangleMesh& posedCards, const LashParams& params) {
  TriangleMesh mesh;
  for (const Lash& lash : lashes) appendTube(mesh, lashCentreline(strips[lash.strip], lash, posedCards), params);
  return mesh;
}

}  // namespace lacrima
