// estimateTetrahedra: the enclosed volume over the cube of the area-weighted boundary size.
#include "mesh/volumes/volume_estimate.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace geomesh {

namespace {

constexpr double kTetrahedraPerSizeCube = 4.7;
constexpr double kBytesPerTetrahedron = 150;
constexpr double kMostTetrahedra = 1e9;  // 32-bit links: 4 per tetrahedron

// The shells' faces as triangles (quadrangles split in two), each with its shell.
struct Face {
  std::array<int, 3> corners;
  std::size_t shell;
};

std::vector<Face> shellFaces(const VolumePlc& plc) {
  std::vector<Face> faces;
  std::size_t shell = 0;
  for (std::size_t t = 0; t < plc.shellEnd; ++t) {
    while (shell + 1 < plc.shellStart.size() && t >= plc.shellStart[shell + 1]) ++shell;
    faces.push_back({plc.triangles[t], shell});
  }
  for (std::size_t q = 0; q < plc.quads.size(); ++q) {
    const auto& c = plc.quads[q];
    faces.push_back({{c[0], c[1], c[2]}, plc.quadShellOf[q]});
    faces.push_back({{c[0], c[2], c[3]}, plc.quadShellOf[q]});
  }
  return faces;
}

}  // namespace

double estimateTetrahedra(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                          const MeshOptions& options) {
  const std::vector<Face> faces = shellFaces(plc);
  if (faces.empty()) return 0;
  std::vector<double> volumes(plc.shellStart.size() + 1, 0);
  const Vec3 origin = xyz[faces.front().corners[0]];
  double area = 0, weighted = 0;
  for (const Face& f : faces) {
    const Vec3 a = xyz[f.corners[0]], b = xyz[f.corners[1]], c = xyz[f.corners[2]];
    volumes[f.shell] += dot(cross(b - origin, c - origin), a - origin) / 6;
    const double faceArea = norm(cross(b - a, c - a)) / 2;
    const double edge = (norm(b - a) + norm(c - b) + norm(a - c)) / 3;
    area += faceArea;
    weighted += faceArea * std::clamp(edge, options.sizeMin, options.sizeMax);
  }
  double volume = std::abs(volumes[0]);
  for (std::size_t s = 1; s < volumes.size(); ++s) volume -= std::abs(volumes[s]);
  if (!(area > 0) || !(volume > 0) || !(weighted > 0)) return 0;
  const double size = weighted / area;
  return kTetrahedraPerSizeCube * volume / (size * size * size);
}

std::string tooManyTetrahedra(double tetrahedra) {
  char count[32];
  std::snprintf(count, sizeof count, "%.2g", tetrahedra);
  if (tetrahedra > kMostTetrahedra)
    return std::string("about ") + count + " tetrahedra: more than the 1e9 one volume can hold";
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return {};
  const double memory = double(pages) * double(pageSize);
  if (tetrahedra * kBytesPerTetrahedron <= memory) return {};
  char gigabytes[32];
  std::snprintf(gigabytes, sizeof gigabytes, "%.0f", memory / 1e9);
  return std::string("about ") + count + " tetrahedra: more than the " + gigabytes +
         " GB of memory here can hold while meshing";
}

}  // namespace geomesh
