// Vertex normals and curvatures: the cotangent mean-curvature normal and the angle deficit,
// each divided by the vertex's mixed Voronoi area (Meyer, Desbrun, Schröder, Barr 2003).
#include "mesh/discrete/surface_curvature.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/discrete/surface_topology.h"

namespace geomesh {
namespace {

struct Corners {
  std::array<Vec3, 3> p;
  double twiceArea;
};

Corners cornersOf(const Triangulation& t, std::uint32_t triangle) {
  const TriangleVertices& v = t.triangles[triangle];
  Corners c{{t.points[v[0]], t.points[v[1]], t.points[v[2]]}, 0};
  c.twiceArea = norm(cross(c.p[1] - c.p[0], c.p[2] - c.p[0]));
  return c;
}

// The part of a triangle's area in each corner's mixed Voronoi region: the circumcentric
// (Voronoi) part on a non-obtuse triangle, else half the area to the obtuse corner and a
// quarter to each other one.
std::array<double, 3> mixedAreas(const Corners& c, const std::array<double, 3>& cot) {
  const double area = 0.5 * c.twiceArea;
  for (int k = 0; k < 3; ++k)
    if (cot[k] < 0) {
      std::array<double, 3> a{0.25 * area, 0.25 * area, 0.25 * area};
      a[k] = 0.5 * area;
      return a;
    }
  std::array<double, 3> a{};
  for (int k = 0; k < 3; ++k) {
    const int next = (k + 1) % 3, previous = (k + 2) % 3;
    const Vec3 toNext = c.p[next] - c.p[k], toPrevious = c.p[previous] - c.p[k];
    a[k] = (dot(toNext, toNext) * cot[previous] + dot(toPrevious, toPrevious) * cot[next]) / 8;
  }
  return a;
}

// Per vertex: the sum of (cot a + cot b)(x_i - x_j) over its edges, its angle sum and its
// mixed area.
struct CurvatureSums {
  std::vector<Vec3> laplacian;
  std::vector<double> angles, area;
};

CurvatureSums curvatureSums(const Triangulation& t) {
  const std::size_t n = t.points.size();
  CurvatureSums s{std::vector<Vec3>(n), std::vector<double>(n, 0), std::vector<double>(n, 0)};
  for (std::uint32_t tri = 0; tri < t.triangles.size(); ++tri) {
    const Corners c = cornersOf(t, tri);
    if (c.twiceArea == 0) continue;
    const std::array<double, 3> cot = cornerCotangents(t, tri);
    const std::array<double, 3> area = mixedAreas(c, cot);
    const TriangleVertices& v = t.triangles[tri];
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3, l = (k + 2) % 3;
      s.laplacian[v[j]] += cot[k] * (c.p[j] - c.p[l]);
      s.laplacian[v[l]] += cot[k] * (c.p[l] - c.p[j]);
      s.angles[v[k]] += std::atan2(c.twiceArea, dot(c.p[j] - c.p[k], c.p[l] - c.p[k]));
      s.area[v[k]] += area[k];
    }
  }
  return s;
}

// Gives each boundary vertex the average of the values at its neighbours nearest (in edge
// hops) to the interior, layer by layer away from the interior vertices.
void spreadToBoundary(const Triangulation& t, std::vector<bool> known,
                      std::vector<double*> values) {
  const std::size_t n = t.points.size();
  std::vector<double> sum(n * values.size());
  std::vector<int> count(n);
  for (bool changed = true; changed;) {
    std::fill(sum.begin(), sum.end(), 0.0);
    std::fill(count.begin(), count.end(), 0);
    for (const TriangleVertices& v : t.triangles)
      for (int k = 0; k < 3; ++k)
        for (int other : {(k + 1) % 3, (k + 2) % 3}) {
          if (known[v[k]] || !known[v[other]]) continue;
          ++count[v[k]];
          for (std::size_t q = 0; q < values.size(); ++q)
            sum[v[k] * values.size() + q] += values[q][v[other]];
        }
    changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (count[i] == 0) continue;
      for (std::size_t q = 0; q < values.size(); ++q)
        values[q][i] = sum[i * values.size() + q] / count[i];
      known[i] = changed = true;
    }
  }
}

}  // namespace

std::array<double, 3> cornerCotangents(const Triangulation& t, std::uint32_t triangle) {
  const Corners c = cornersOf(t, triangle);
  if (c.twiceArea == 0) return {0, 0, 0};
  std::array<double, 3> cot{};
  for (int k = 0; k < 3; ++k)
    cot[k] = dot(c.p[(k + 1) % 3] - c.p[k], c.p[(k + 2) % 3] - c.p[k]) / c.twiceArea;
  return cot;
}

std::vector<Vec3> vertexNormals(const Triangulation& t) {
  std::vector<Vec3> normals(t.points.size());
  for (std::uint32_t tri = 0; tri < t.triangles.size(); ++tri) {
    const Corners c = cornersOf(t, tri);
    if (c.twiceArea == 0) continue;
    const Vec3 n = cross(c.p[1] - c.p[0], c.p[2] - c.p[0]) / c.twiceArea;
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = c.p[(k + 1) % 3] - c.p[k], b = c.p[(k + 2) % 3] - c.p[k];
      normals[t.triangles[tri][k]] += std::atan2(c.twiceArea, dot(a, b)) * n;
    }
  }
  for (Vec3& n : normals) n = normalized(n);
  return normals;
}

VertexCurvatures vertexCurvatures(const Triangulation& t) {
  const std::size_t n = t.points.size();
  const CurvatureSums s = curvatureSums(t);
  const std::vector<Vec3> normals = vertexNormals(t);
  const std::vector<bool> onBoundary = boundaryVertices(t);
  VertexCurvatures c{std::vector<double>(n, 0), std::vector<double>(n, 0),
                     std::vector<double>(n, 0)};
  std::vector<bool> known(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    if (onBoundary[i] || s.area[i] <= 0) continue;
    // The mean-curvature normal 2 H n is the Laplacian over twice the mixed area.
    const Vec3 meanCurvatureNormal = s.laplacian[i] / (2 * s.area[i]);
    const double h = 0.5 * norm(meanCurvatureNormal);
    c.mean[i] = dot(meanCurvatureNormal, normals[i]) < 0 ? -h : h;
    c.gaussian[i] = (2 * std::numbers::pi - s.angles[i]) / s.area[i];
    known[i] = true;
  }
  spreadToBoundary(t, known, {c.mean.data(), c.gaussian.data()});
  for (std::size_t i = 0; i < n; ++i) {
    const double h = c.mean[i], k = c.gaussian[i];
    c.maxAbs[i] = std::abs(h) + std::sqrt(std::max(0.0, h * h - k));
  }
  return c;
}

}  // namespace geomesh
