// Tests of the filtered exact predicates against exact integer arithmetic, degenerate cases
// included.
#include "mesh/core/predicates.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

namespace geomesh {
namespace {

using I = std::int64_t;

int sign(I v) {
  return (v > 0) - (v < 0);
}

// Exact determinants for small integer coordinates (|c| <= 64: every product fits in 63 bits).
I det3(I a0, I a1, I a2, I b0, I b1, I b2, I c0, I c1, I c2) {
  return a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0);
}

int exactOrient2d(const I* a, const I* b, const I* c) {
  return sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

int exactIncircle(const I* a, const I* b, const I* c, const I* d) {
  I r[3][3];
  const I* p[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    r[i][0] = p[i][0] - d[0];
    r[i][1] = p[i][1] - d[1];
    r[i][2] = r[i][0] * r[i][0] + r[i][1] * r[i][1];
  }
  return sign(det3(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1],
                   r[2][2]));
}

int exactOrient3d(const I* a, const I* b, const I* c, const I* d) {
  return sign(det3(b[0] - a[0], b[1] - a[1], b[2] - a[2], c[0] - a[0], c[1] - a[1], c[2] - a[2],
                   d[0] - a[0], d[1] - a[1], d[2] - a[2]));
}

// For a positive tetrahedron: +1 when e is inside its circumsphere.
int exactInsphere(const I* a, const I* b, const I* c, const I* d, const I* e) {
  const I* p[4] = {a, b, c, d};
  I r[4][4];
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) r[i][k] = p[i][k] - e[k];
    r[i][3] = r[i][0] * r[i][0] + r[i][1] * r[i][1] + r[i][2] * r[i][2];
  }
  I det = 0;
  for (int col = 0; col < 4; ++col) {
    I minor[9];
    int m = 0;
    for (int i = 1; i < 4; ++i)
      for (int k = 0; k < 4; ++k)
        if (k != col) minor[m++] = r[i][k];
    const I cofactor = det3(minor[0], minor[1], minor[2], minor[3], minor[4], minor[5],
                            minor[6], minor[7], minor[8]);
    det += (col % 2 ? -1 : 1) * r[0][col] * cofactor;
  }
  // The lifted determinant with rows a, b, c, d is negative for e inside a positive one.
  return -sign(det);
}

Vec2 v2(const I* p) {
  return {double(p[0]), double(p[1])};
}
Vec3 v3(const I* p) {
  return {double(p[0]), double(p[1]), double(p[2])};
}

TEST(Predicates, AgreeWithExactIntegerArithmeticIncludingDegenerateCases) {
  // Coordinates from a small range: many collinear, coplanar, cocircular and cospherical sets.
  std::mt19937 random(17);
  std::uniform_int_distribution<int> pick(-4, 4);
  int zeros2 = 0, zeros3 = 0, inside = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    I p[5][3];
    for (auto& q : p)
      for (I& c : q) c = pick(random) * 7;
    ASSERT_EQ(orient2d(v2(p[0]), v2(p[1]), v2(p[2])), exactOrient2d(p[0], p[1], p[2]));
    if (exactOrient2d(p[0], p[1], p[2]) > 0) {
      const int expected = exactIncircle(p[0], p[1], p[2], p[3]);
      ASSERT_EQ(incircle(v2(p[0]), v2(p[1]), v2(p[2]), v2(p[3])), expected);
      zeros2 += expected == 0;
    }
    const int o = exactOrient3d(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(orient3d(v3(p[0]), v3(p[1]), v3(p[2]), v3(p[3])), o);
    if (o > 0) {
      const int expected = exactInsphere(p[0], p[1], p[2], p[3], p[4]);
      ASSERT_EQ(insphere(v3(p[0]), v3(p[1]), v3(p[2]), v3(p[3]), v3(p[4])), expected);
      zeros3 += expected == 0;
      inside += expected > 0;
    }
  }
  EXPECT_GT(zeros2, 100);  // the degenerate cases were met, and decided exactly
  EXPECT_GT(zeros3, 100);
  EXPECT_GT(inside, 100);
}

TEST(Predicates, NearlyDegenerateInputIsDecidedExactly) {
  // Points a few units in the last place off a plane and a sphere: the filter cannot decide,
  // the exact predicate does, consistently under permutation.
  const Vec3 a{0.1, 0.2, 0.3}, b{1.7, 0.2, 0.3}, c{0.1, 2.9, 0.3};
  const Vec3 above{0.5, 0.5, std::nextafter(0.3, 1.0)}, on{0.5, 0.5, 0.3};
  EXPECT_EQ(orient3d(a, b, c, above), 1);
  EXPECT_EQ(orient3d(b, a, c, above), -1);
  EXPECT_EQ(orient3d(a, b, c, on), 0);
  const Vec2 p{0.1, 0.1}, q{0.7, 0.1}, r{0.1, 0.3};
  EXPECT_EQ(orient2d(p, q, {0.4, std::nextafter(0.1, 1.0)}), 1);
  EXPECT_EQ(orient2d(p, q, {0.4, 0.1}), 0);
  EXPECT_EQ(incircle(p, q, r, {0.7, 0.3}), 0);  // the fourth corner of the rectangle
}

}  // namespace
}  // namespace geomesh
