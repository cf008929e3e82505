// estimateTetrahedra: the enclosed volume over the cube of the area-weighted boundary size.
#include "mesh/volumes/volume_estimate.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace geomesh {

namespace {

constexpr double kTetrahedraPerSizeCube = 4.7;
constexpr double kBytesPerTetrahedron = 150;
constexpr double kMostTetrahedra = 1e9;  // 32-bit links: 4 per tetrahedron

double shellVolume(const VolumePlc& plc, const std::vector<Vec3>& xyz, std::size_t shell) {
  const std::size_t first = plc.shellStart[shell], last = plc.shellEndOf(shell);
  if (first == last) return 0;
  const Vec3 origin = xyz[plc.triangles[first][0]];
  double volume = 0;
  for (std::size_t t = first; t < last; ++t) {
    const PlcTriangle& c = plc.triangles[t];
    volume += dot(cross(xyz[c[1]] - origin, xyz[c[2]] - origin), xyz[c[0]] - origin) / 6;
  }
  return std::abs(volume);
}

}  // namespace

double estimateTetrahedra(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                          const std::vector<double>& sizes) {
  if (plc.shellStart.empty()) return 0;
  double volume = shellVolume(plc, xyz, 0);
  for (std::size_t s = 1; s < plc.shellStart.size(); ++s) volume -= shellVolume(plc, xyz, s);
  double area = 0, weighted = 0;
  for (std::size_t t = 0; t < plc.shellEnd; ++t) {
    const PlcTriangle& c = plc.triangles[t];
    const double a = norm(cross(xyz[c[1]] - xyz[c[0]], xyz[c[2]] - xyz[c[0]])) / 2;
    area += a;
    weighted += a * (sizes[c[0]] + sizes[c[1]] + sizes[c[2]]) / 3;
  }
  if (!(area > 0) || !(volume > 0)) return 0;
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
