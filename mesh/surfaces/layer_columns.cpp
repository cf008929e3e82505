// Layer columns in the plane: directions, heights, fans, cells, and their shortening.
#include "mesh/surfaces/layer_columns.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace geomesh {
namespace {

Vec2 plus(Vec2 a, Vec2 b) {
  return {a.u + b.u, a.v + b.v};
}
Vec2 minus(Vec2 a, Vec2 b) {
  return {a.u - b.u, a.v - b.v};
}
Vec2 scaled(double s, Vec2 a) {
  return {s * a.u, s * a.v};
}
double dot2(Vec2 a, Vec2 b) {
  return a.u * b.u + a.v * b.v;
}
double cross2(Vec2 a, Vec2 b) {
  return a.u * b.v - a.v * b.u;
}
double length(Vec2 a) {
  return std::hypot(a.u, a.v);
}
Vec2 unit(Vec2 a) {
  const double l = length(a);
  return l > 0 ? scaled(1 / l, a) : Vec2{};
}
Vec2 rotated(Vec2 a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * a.u - s * a.v, s * a.u + c * a.v};
}

std::size_t previous(std::size_t i, std::size_t n) {
  return (i + n - 1) % n;
}
std::size_t following(std::size_t i, std::size_t n) {
  return (i + 1) % n;
}

// The unit normal of a segment's direction pointing into the surface.
Vec2 inwardNormal(const LayerWall& wall, Vec2 along) {
  const Vec2 left{-along.v, along.u};
  return wall.domainLeft ? left : scaled(-1, left);
}

LayerColumn column(Vec2 base, Vec2 direction, std::vector<double> heights) {
  LayerColumn c{base, direction, std::move(heights), 0};
  c.levels = c.heights.size();
  return c;
}

// A turn sharper than this at a fan point (radians) makes a fan; flatter, one column.
constexpr double kFanTurn = 1e-3;
// A single column's heights grow by at most this factor at a sharp corner.
constexpr double kMaxStretch = 2;

std::vector<LayerColumn> nodeColumns(const LayerWall& wall, std::size_t i, int fanElements) {
  const std::size_t n = wall.xy.size();
  const BoundaryLayerParameters& p = *wall.layer[previous(i, n)];
  const Vec2 tIn = unit(minus(wall.xy[i], wall.xy[previous(i, n)]));
  const Vec2 tOut = unit(minus(wall.xy[following(i, n)], wall.xy[i]));
  const Vec2 nIn = inwardNormal(wall, tIn), nOut = inwardNormal(wall, tOut);
  const double side = wall.domainLeft ? 1 : -1;
  const double turn = std::atan2(side * cross2(tIn, tOut), dot2(tIn, tOut));  // > 0: concave
  const int point = wall.point[i];
  const std::vector<double> heights = p.heights(point ? p.firstHeight(point) : p.size);
  const BoundaryLayerParameters& next = *wall.layer[i];
  if (point && turn < -kFanTurn && (p.isFanPoint(point) || next.isFanPoint(point))) {
    const int count = std::max(1, p.isFanPoint(point) ? p.fanElements(point, fanElements)
                                                      : next.fanElements(point, fanElements));
    std::vector<LayerColumn> fan;
    for (int j = 0; j <= count; ++j)
      fan.push_back(column(wall.xy[i], rotated(nIn, side * turn * j / count), heights));
    return fan;
  }
  Vec2 direction = unit(plus(nIn, nOut));
  if (length(plus(nIn, nOut)) < 1e-3) direction = unit(minus(tIn, tOut));
  const double stretch = 1 / std::max(dot2(direction, nIn), 1 / kMaxStretch);
  std::vector<double> stretched = heights;
  for (double& h : stretched) h *= stretch;
  return {column(wall.xy[i], direction, std::move(stretched))};
}

// Where the ray from `from` along `direction` first meets segment a-b (infinity if never).
double rayHit(Vec2 from, Vec2 direction, Vec2 a, Vec2 b) {
  const Vec2 ab = minus(b, a);
  const double denominator = cross2(direction, ab);
  if (std::abs(denominator) < 1e-300) return std::numeric_limits<double>::infinity();
  const Vec2 fa = minus(a, from);
  const double t = cross2(fa, ab) / denominator;
  const double s = cross2(fa, direction) / denominator;
  if (t <= 0 || s < 0 || s > 1) return std::numeric_limits<double>::infinity();
  return t;
}

// How far the column may reach: 0.45 of the way to the nearest wall segment not touching it.
double reach(std::span<const LayerWall> walls, const LayerColumn& c) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const LayerWall& w : walls)
    for (std::size_t k = 0; k < w.xy.size(); ++k) {
      const Vec2 a = w.xy[k], b = w.xy[following(k, w.xy.size())];
      if (a == c.base || b == c.base) continue;
      nearest = std::min(nearest, rayHit(c.base, c.direction, a, b));
    }
  constexpr double kShare = 0.45;
  return kShare * nearest;
}

// Whether the cell's corners make a convex polygon turning the wall's way.
bool validCell(const std::vector<Vec2>& corners, bool domainLeft, double scale) {
  if (corners.size() < 3) return true;  // collapsed to nothing: no element
  const double side = domainLeft ? 1 : -1;
  const double tiny = 1e-12 * scale * scale;
  const std::size_t m = corners.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2 a = corners[k], b = corners[(k + 1) % m], c = corners[(k + 2) % m];
    if (!(side * cross2(minus(b, a), minus(c, a)) > tiny)) return false;
  }
  return true;
}

// The two columns a cell lies between.
LayerColumn& columnA(WallColumns& columns, const LayerCell& cell) {
  return columns[cell.node][cell.a];
}
LayerColumn& columnB(const LayerWall& wall, WallColumns& columns, const LayerCell& cell) {
  return columns[cell.acrossSegment ? following(cell.node, wall.xy.size()) : cell.node][cell.b];
}

// Removes the cell and those above it from both its columns.
void cutAt(const LayerWall& wall, WallColumns& columns, const LayerCell& cell) {
  LayerColumn& a = columnA(columns, cell);
  LayerColumn& b = columnB(wall, columns, cell);
  a.levels = std::min(a.levels, cell.level);
  b.levels = std::min(b.levels, cell.level);
}

double wallScale(const LayerWall& wall) {
  double scale = 0;
  for (std::size_t k = 0; k < wall.xy.size(); ++k)
    scale = std::max(scale, length(minus(wall.xy[k], wall.xy[following(k, wall.xy.size())])));
  return scale;
}

bool shortenInvalidCells(const LayerWall& wall, WallColumns& columns) {
  const double scale = wallScale(wall);
  bool changed = false;
  forEachCell(wall, columns, [&](const LayerCell& cell) {
    if (validCell(cellCorners(wall, columns, cell), wall.domainLeft, scale)) return;
    cutAt(wall, columns, cell);
    changed = true;
  });
  return changed;
}

// Whether two convex polygons (or a polygon and a segment) overlap by more than `tiny` along
// every separating direction (their edges' normals): cells that only share an edge or a
// corner do not.
bool overlapping(const std::vector<Vec2>& p, const std::vector<Vec2>& q, double tiny) {
  for (const std::vector<Vec2>* poly : {&p, &q})
    for (std::size_t k = 0; k < poly->size(); ++k) {
      const Vec2 edge = minus((*poly)[(k + 1) % poly->size()], (*poly)[k]);
      const double l = length(edge);
      if (!(l > 0)) continue;
      const Vec2 normal{-edge.v / l, edge.u / l};
      double pLow = 1e300, pHigh = -1e300, qLow = 1e300, qHigh = -1e300;
      for (Vec2 v : p) {
        pLow = std::min(pLow, dot2(v, normal));
        pHigh = std::max(pHigh, dot2(v, normal));
      }
      for (Vec2 v : q) {
        qLow = std::min(qLow, dot2(v, normal));
        qHigh = std::max(qHigh, dot2(v, normal));
      }
      // How far one must move to part them along `normal` (for a segment, whose extent
      // across itself is nil, how deep its line cuts the other).
      if (std::min(pHigh - qLow, qHigh - pLow) <= tiny) return false;
    }
  return true;
}

// Cuts the columns of every two cells (of any walls) that overlap, and of every cell that a
// wall segment crosses: the layers of two walls meeting at a concave corner, or of walls
// facing each other, which the rays of `reach` do not see when the columns run alongside
// the other wall, and the tip of a wall reaching into a cell between two columns whose rays
// pass either side of it. Cells and segments are swept in order of their smallest abscissa.
bool shortenOverlappingCells(std::span<const LayerWall> walls, std::span<WallColumns> columns) {
  struct Placed {
    std::size_t wall;
    LayerCell cell;
    std::vector<Vec2> corners;  // a cell's, or a wall segment's two ends
    bool segment;
    double xLow = 1e300, xHigh = -1e300, yLow = 1e300, yHigh = -1e300;
  };
  std::vector<Placed> items;
  auto place = [&](Placed placed) {
    for (Vec2 v : placed.corners) {
      placed.xLow = std::min(placed.xLow, v.u);
      placed.xHigh = std::max(placed.xHigh, v.u);
      placed.yLow = std::min(placed.yLow, v.v);
      placed.yHigh = std::max(placed.yHigh, v.v);
    }
    items.push_back(std::move(placed));
  };
  double scale = 0;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const LayerWall& wall = walls[w];
    scale = std::max(scale, wallScale(wall));
    forEachCell(wall, columns[w], [&](const LayerCell& cell) {
      std::vector<Vec2> corners = cellCorners(wall, columns[w], cell);
      if (corners.size() >= 3) place({w, cell, std::move(corners), false});
    });
    for (std::size_t k = 0; k < wall.xy.size(); ++k)
      place({w, {}, {wall.xy[k], wall.xy[following(k, wall.xy.size())]}, true});
  }
  std::sort(items.begin(), items.end(),
            [](const Placed& a, const Placed& b) { return a.xLow < b.xLow; });
  const double tiny = 1e-9 * scale;
  std::vector<std::size_t> cut;
  for (std::size_t i = 0; i < items.size(); ++i)
    for (std::size_t j = i + 1; j < items.size() && items[j].xLow < items[i].xHigh - tiny; ++j) {
      const Placed& a = items[i];
      const Placed& b = items[j];
      if (a.segment && b.segment) continue;
      if (a.yHigh - tiny <= b.yLow || b.yHigh - tiny <= a.yLow) continue;
      if (!overlapping(a.corners, b.corners, tiny)) continue;
      if (!a.segment) cut.push_back(i);
      if (!b.segment) cut.push_back(j);
    }
  for (std::size_t i : cut) cutAt(walls[items[i].wall], columns[items[i].wall], items[i].cell);
  return !cut.empty();
}

}  // namespace

Vec2 LayerColumn::at(std::size_t k) const {
  return k == 0 ? base : plus(base, scaled(heights[k - 1], direction));
}

WallColumns layerColumns(const LayerWall& wall, int fanElements) {
  const std::size_t n = wall.xy.size();
  WallColumns columns(n);
  if (n < 3) return columns;
  std::vector<std::uint8_t> wanted(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    wanted[i] = wall.layer[previous(i, n)] && wall.layer[i] ? 1 : 0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool alone = !wanted[previous(i, n)] && !wanted[following(i, n)];
    if (wanted[i] && !alone) columns[i] = nodeColumns(wall, i, fanElements);
  }
  return columns;
}

void forEachCell(const LayerWall& wall, const WallColumns& columns,
                 const std::function<void(const LayerCell&)>& visit) {
  const std::size_t n = wall.xy.size();
  auto cellsBetween = [&](const LayerColumn& a, const LayerColumn& b, LayerCell cell) {
    for (std::size_t level = 0; level < std::max(a.levels, b.levels); ++level) {
      cell.level = level;
      visit(cell);
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<LayerColumn>& here = columns[i];
    for (std::size_t j = 0; j + 1 < here.size(); ++j)
      cellsBetween(here[j], here[j + 1], {i, j, j + 1, false, 0});
    const std::vector<LayerColumn>& next = columns[following(i, n)];
    if (!here.empty() && !next.empty())
      cellsBetween(here.back(), next.front(), {i, here.size() - 1, 0, true, 0});
  }
}

std::vector<Vec2> cellCorners(const LayerWall& wall, const WallColumns& columns,
                              const LayerCell& cell) {
  const LayerColumn& a = columns[cell.node][cell.a];
  const LayerColumn& b =
      columns[cell.acrossSegment ? following(cell.node, wall.xy.size()) : cell.node][cell.b];
  auto clamp = [](const LayerColumn& c, std::size_t k) { return c.at(std::min(k, c.levels)); };
  const Vec2 ring[4] = {clamp(a, cell.level), clamp(b, cell.level), clamp(b, cell.level + 1),
                        clamp(a, cell.level + 1)};
  std::vector<Vec2> corners;
  for (Vec2 p : ring)
    if (corners.empty() || !(corners.back() == p)) corners.push_back(p);
  while (corners.size() > 1 && corners.back() == corners.front()) corners.pop_back();
  return corners;
}

std::vector<Vec2> limitColumns(std::span<const LayerWall> walls, std::span<WallColumns> columns) {
  std::vector<std::vector<std::vector<std::size_t>>> before(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w)
    for (std::vector<LayerColumn>& node : columns[w]) {
      before[w].emplace_back();
      for (LayerColumn& c : node) {
        before[w].back().push_back(c.levels);
        const double limit = reach(walls, c);
        while (c.levels > 0 && c.heights[c.levels - 1] > limit) --c.levels;
      }
    }
  // Each pass removes at least one cell: the passes end.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t w = 0; w < walls.size(); ++w)
      while (shortenInvalidCells(walls[w], columns[w])) changed = true;
    if (shortenOverlappingCells(walls, columns)) changed = true;
  }
  std::vector<Vec2> shortened;
  for (std::size_t w = 0; w < walls.size(); ++w)
    for (std::size_t i = 0; i < columns[w].size(); ++i)
      for (std::size_t j = 0; j < columns[w][i].size(); ++j)
        if (columns[w][i][j].levels < before[w][i][j]) {
          shortened.push_back(columns[w][i][j].base);
          break;
        }
  return shortened;
}

}  // namespace geomesh
