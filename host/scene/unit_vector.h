// A vector's direction at unit length, for vectors of any finite size: glm::normalize squares
// the components, which underflows to 0 below about 1e-154 (and overflows above 1e154),
// giving NaN or 0 for a direction that the scene states clearly (`rotate 1e-200 0 0 45`).
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace vkrt {

// v times the power of two that brings its largest component into [1, 2) when it lies
// outside [2^-500, 2^500] (else v as it is): the same direction, exactly, and squares that
// neither underflow nor overflow. The zero vector, or one with a component that is not
// finite, gives the zero vector.
inline glm::dvec3 scaledForSquares(const glm::dvec3& v) {
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(largest > 0.0) || !std::isfinite(largest)) return glm::dvec3(0.0);
  if (largest >= 0x1p-500 && largest <= 0x1p500) return v;
  return v * std::ldexp(1.0, -std::ilogb(largest));
}

// v / |v| (glm::normalize of scaledForSquares(v): for vectors of ordinary size the bits of
// glm::normalize); the zero vector for a zero or non-finite v.
inline glm::dvec3 unitVector(const glm::dvec3& v) {
  const glm::dvec3 s = scaledForSquares(v);
  return s == glm::dvec3(0.0) ? s : glm::normalize(s);
}

// |v|: glm::length where its square neither underflows nor overflows (the same bits), else
// computed from v scaled by its largest component.
inline double lengthOf(const glm::dvec3& v) {
  const double l = glm::length(v);
  if (std::isfinite(l) && (l > 0.0 || v == glm::dvec3(0.0))) return l;
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  return std::isfinite(largest) ? largest * glm::length(v / largest) : largest;
}

}  // namespace vkrt
