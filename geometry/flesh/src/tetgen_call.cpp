#include "tetgen_call.hpp"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>

#include "lacrima/flesh/flesh_volume.hpp"
// Debian builds libtet with TETLIBRARY: the switches-string entry point, and errors thrown as int.
#define TETLIBRARY
#include <tetgen.h>

namespace lacrima::flesh {

namespace {

// What the child sends back: a status (0, or TetGen's error code), then the mesh's sizes and arrays.
struct Reply {
  int status = 0;
  int points = 0, tets = 0;
};

void fillInput(const std::vector<Vec3d>& points, const std::vector<std::array<int, 3>>& facets,
               const std::vector<int>& facetMarkers, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = int(points.size());
  in.pointlist = new REAL[points.size() * 3];
  for (size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + size_t(k)] = points[i][k];
  in.numberoffacets = int(facets.size());
  in.facetlist = new tetgenio::facet[facets.size()];
  in.facetmarkerlist = new int[facets.size()];
  for (size_t f = 0; f < facets.size(); ++f) in.facetmarkerlist[f] = facetMarkers[f];
  for (size_t f = 0; f < facets.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3]{facets[f][0], facets[f][1], facets[f][2]};
  }
}

bool writeAll(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= size_t(n);
  }
  return true;
}

[[noreturn]] void runChild(int fd, const std::vector<Vec3d>& points, const std::vector<std::array<int, 3>>& facets,
                           const std::vector<int>& facetMarkers, std::string switches) {
  Reply reply;
  tetgenio in, out;
  fillInput(points, facets, facetMarkers, in);
  try {
    tetrahedralize(switches.data(), &in, &out);
    reply.points = out.numberofpoints;
    reply.tets = out.numberoftetrahedra;
  } catch (int code) {
    reply.status = code > 0 ? code : 1;
  }
  bool ok = writeAll(fd, &reply, sizeof reply);
  if (reply.status == 0) {
    ok = ok && writeAll(fd, out.pointlist, sizeof(REAL) * 3 * size_t(reply.points));
    for (int t = 0; ok && t < reply.tets; ++t)
      ok = writeAll(fd, out.tetrahedronlist + size_t(t) * size_t(out.numberofcorners), sizeof(int) * 4);
    std::vector<int> markers(size_t(reply.points), 0);
    if (out.pointmarkerlist) std::copy(out.pointmarkerlist, out.pointmarkerlist + reply.points, markers.begin());
    ok = ok && writeAll(fd, markers.data(), sizeof(int) * markers.size());
  }
  ::_exit(ok ? 0 : 1);
}

std::string readAll(int fd) {
  std::string data;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    data.append(buffer, size_t(n));
  }
  return data;
}

std::string describeTetGenError(int code) {
  switch (code) {
    case 1: return "out of memory";
    case 3: return "facets of the boundary intersect";
    case 4: case 5: return "facets of the boundary are too close or overlap";
    default: return "the boundary could not be meshed";
  }
}

}  // namespace

TetGenResult tetrahedralizeInChildProcess(const std::vector<Vec3d>& points, const std::vector<std::array<int, 3>>& facets,
                                          const std::vector<int>& facetMarkers, const std::string& switches) {
  int fds[2];
  if (::pipe(fds) != 0) throw FleshVolumeError(fmt::format("cannot start TetGen: pipe: {}", std::strerror(errno)));
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw FleshVolumeError(fmt::format("cannot start TetGen: fork: {}", std::strerror(errno)));
  }
  if (child == 0) {
    ::close(fds[0]);
    runChild(fds[1], points, facets, facetMarkers, switches);
  }
  ::close(fds[1]);
  const std::string data = readAll(fds[0]);
  ::close(fds[0]);
  int wstatus = 0;
  while (::waitpid(child, &wstatus, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(wstatus))
    throw FleshVolumeError(fmt::format("TetGen crashed (signal {}) meshing the flesh volume: its boundary is not a clean "
                                       "closed surface (a smaller depth or a smoother region usually helps)",
                                       WTERMSIG(wstatus)));
  Reply reply;
  if (data.size() < sizeof reply) throw FleshVolumeError("TetGen ended without an answer");
  std::memcpy(&reply, data.data(), sizeof reply);
  if (reply.status != 0)
    throw FleshVolumeError(fmt::format("TetGen could not mesh the flesh volume: {} (its error {}); a smaller depth or "
                                       "a region with a smoother border usually helps",
                                       describeTetGenError(reply.status), reply.status));
  const size_t expected = sizeof reply + sizeof(double) * 3 * size_t(reply.points) + sizeof(int) * 4 * size_t(reply.tets) +
                          sizeof(int) * size_t(reply.points);
  if (data.size() != expected || !WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0)
    throw FleshVolumeError("TetGen's answer was cut short");
  TetGenResult result;
  TetMesh& mesh = result.mesh;
  const char* p = data.data() + sizeof reply;
  mesh.nodes.resize(size_t(reply.points));
  for (Vec3d& node : mesh.nodes) {
    std::memcpy(node.data(), p, sizeof(double) * 3);
    p += sizeof(double) * 3;
  }
  mesh.tets.resize(size_t(reply.tets));
  for (Tet& tet : mesh.tets) {
    std::memcpy(tet.data(), p, sizeof(int) * 4);
    p += sizeof(int) * 4;
  }
  result.nodeMarkers.resize(size_t(reply.points));
  std::memcpy(result.nodeMarkers.data(), p, sizeof(int) * result.nodeMarkers.size());
  return result;
}

}  // namespace lacrima::flesh
