// Determinant tests and inverses of transforms with very small or very large scales: the
// determinant of `scale 1e-150 1e-150 1e-150` (1e-450) underflows double, and glm::inverse
// divides by it. Each column is first scaled by a power of two (exact) into [1, 2) when its
// largest entry lies outside [2^-300, 2^300] (so that a product of three stays in range);
// transforms of ordinary size are left as they are, so their results keep glm's bits.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace vkrt {

// The power of two per column of `a` described above (1 for an ordinary or zero column).
inline glm::dvec3 columnScales(const glm::dmat3& a) {
  glm::dvec3 s(1.0);
  for (int c = 0; c < 3; ++c) {
    const double largest = std::max({std::abs(a[c].x), std::abs(a[c].y), std::abs(a[c].z)});
    if (largest > 0.0 && std::isfinite(largest) && (largest < 0x1p-300 || largest > 0x1p300))
      s[c] = std::ldexp(1.0, -std::ilogb(largest));
  }
  return s;
}

// Whether the linear part has no inverse (a zero determinant once its columns are scaled).
inline bool isSingular(const glm::dmat3& a) {
  const glm::dvec3 s = columnScales(a);
  const double det = glm::determinant(glm::dmat3(a[0] * s.x, a[1] * s.y, a[2] * s.z));
  return !(det != 0.0) || !std::isfinite(det);
}

// The inverse of the linear map a: with N = a S (S the column scales), a^-1 = S N^-1.
inline glm::dmat3 inverseLinear(const glm::dmat3& a) {
  const glm::dvec3 s = columnScales(a);
  if (s == glm::dvec3(1.0)) return glm::inverse(a);
  glm::dmat3 inv = glm::inverse(glm::dmat3(a[0] * s.x, a[1] * s.y, a[2] * s.z));
  for (int c = 0; c < 3; ++c) inv[c] *= s;   // row r times s[r]
  return inv;
}

// The inverse of an affine transform (last row 0 0 0 1), by inverseLinear for its linear part.
inline glm::dmat4 inverseAffine(const glm::dmat4& m) {
  const glm::dmat3 a(m);
  if (columnScales(a) == glm::dvec3(1.0)) return glm::inverse(m);
  const glm::dmat3 inv = inverseLinear(a);
  glm::dmat4 r(inv);
  r[3] = glm::dvec4(-(inv * glm::dvec3(m[3])), 1.0);
  return r;
}

}  // namespace vkrt
