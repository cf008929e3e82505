// PointCloud: nearest-point distances over a fixed set of points, by a k-d tree in one array.
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/vec3.h"

namespace geomesh {

// Nearest-point queries on a fixed set of points: a k-d tree stored in one array (the points
// reordered so that each subtree is a contiguous range split at its middle element).
class PointCloud {
 public:
  explicit PointCloud(std::vector<Vec3> points);
  bool empty() const { return points_.empty(); }
  // Distance from p to the nearest point; 1e22 when there are none.
  double distanceTo(Vec3 p) const;
  struct Nearest {
    std::uint32_t index;  // in the order the points were given
    double distance;
  };
  // The nearest point to p; the cloud must not be empty.
  Nearest nearest(Vec3 p) const;

 private:
  struct Entry {
    Vec3 point;
    std::uint32_t index;
  };
  void build(std::vector<Entry>& entries, std::uint32_t begin, std::uint32_t end);
  void search(Vec3 p, std::uint32_t begin, std::uint32_t end, double& best2,
              std::uint32_t& best) const;
  std::vector<Vec3> points_;
  std::vector<std::uint32_t> original_;  // index given of each stored point
  std::vector<std::uint8_t> axis_;  // split axis of the subtree whose middle element is k
};

}  // namespace geomesh
