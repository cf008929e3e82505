// Helpers of local remeshing: the gamma quality, the logarithmic mean, the domain's triangles.
#include "mesh/surfaces/local_remeshing.h"

#include <cmath>

namespace geomesh {

double planarGamma(Vec2 a, Vec2 b, Vec2 c) {
  const double area = 0.5 * ((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
  if (!(area > 0)) return 0;
  const auto length = [](Vec2 p, Vec2 q) {
    const double du = p.u - q.u, dv = p.v - q.v;
    return std::sqrt(du * du + dv * dv);
  };
  const double la = length(c, b), lb = length(a, c), lc = length(b, a);
  return 16 * area * area / (la * lb * lc * (la + lb + lc));
}

double logarithmicMean(double x, double y) {
  if (std::abs(x - y) <= 1e-6 * (x + y)) return 0.5 * (x + y);
  return (y - x) / std::log(y / x);
}

Triangulation2D domainOf(const Triangulation2D& tri, const std::vector<std::uint8_t>& inside) {
  Triangulation2D domain = tri;
  domain.keepTriangles(inside);
  return domain;
}

}  // namespace geomesh
