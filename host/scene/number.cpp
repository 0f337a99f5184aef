// Number parsing for scene files. std::from_chars is exact and locale-free but takes no '+'
// and is slow in this libstdc++; the common case (a short plain decimal) has a fast path.
#include "scene/number.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace vkrt {
namespace {

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Clinger's fast path: a decimal with at most 15 significant digits (so the integer mantissa
// is exact in a double) and a power of ten up to 1e22 (also exact) is correctly rounded by a
// single multiplication or division. Returns false when the token needs the general parser.
bool parseSimpleDecimal(const char* p, const char* end, double& value) {
  bool negative = false;
  if (p != end && (*p == '-' || *p == '+')) negative = *p++ == '-';
  std::uint64_t mantissa = 0;
  int digits = 0, scale = 0;
  bool any = false;
  for (; p != end && *p >= '0' && *p <= '9'; ++p, any = true) {
    if (mantissa == 0 && *p == '0') continue;   // leading zeros are not significant
    if (++digits > 15) return false;
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p - '0');
  }
  if (p != end && *p == '.') {
    for (++p; p != end && *p >= '0' && *p <= '9'; ++p, any = true) {
      --scale;
      if (mantissa == 0 && *p == '0') continue;
      if (++digits > 15) return false;
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p - '0');
    }
  }
  if (!any) return false;
  if (p != end && (*p == 'e' || *p == 'E')) {
    ++p;
    bool expNegative = false;
    if (p != end && (*p == '-' || *p == '+')) expNegative = *p++ == '-';
    if (p == end) return false;
    int e = 0;
    for (; p != end && *p >= '0' && *p <= '9'; ++p) {
      if (e > 1000) return false;
      e = e * 10 + (*p - '0');
    }
    scale += expNegative ? -e : e;
  }
  if (p != end) return false;
  if (scale < -22 || scale > 22) return false;
  double m = static_cast<double>(mantissa);
  value = scale >= 0 ? m * kPow10[scale] : m / kPow10[-scale];
  if (negative) value = -value;
  return true;
}

// For a decimal that from_chars found out of range: whether its magnitude is below 1 (it
// underflows) rather than above (it overflows). The decimal exponent of its first non-zero
// digit decides; an all-zero mantissa is never out of range.
bool belowOne(const char* p, const char* end) {
  if (p != end && (*p == '-' || *p == '+')) ++p;
  long long position = 0;   // the power of ten of the first non-zero digit, before the exponent
  bool found = false, point = false;
  long long intDigits = 0, leadingFractionZeros = 0;
  for (; p != end && *p != 'e' && *p != 'E'; ++p) {
    if (*p == '.') {
      point = true;
    } else if (!found && *p == '0') {
      if (point) ++leadingFractionZeros;
    } else if (!found) {
      found = true;
      if (!point) ++intDigits;
    } else if (!point) {
      ++intDigits;
    }
  }
  position = intDigits > 0 ? intDigits - 1 : -(leadingFractionZeros + 1);
  long long exponent = 0;
  bool negative = false;
  if (p != end) {   // 'e'
    ++p;
    if (p != end && (*p == '-' || *p == '+')) negative = *p++ == '-';
    for (; p != end; ++p)
      if (exponent < 1000000000LL) exponent = exponent * 10 + (*p - '0');   // saturates: only the sign matters
  }
  return position + (negative ? -exponent : exponent) < 0;
}

}  // namespace

NumberStatus parseNumber(std::string_view token, double& value) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (parseSimpleDecimal(first, last, value)) return NumberStatus::Ok;
  if (first != last && *first == '+') {
    ++first;
    if (first != last && (*first == '-' || *first == '+')) return NumberStatus::NotANumber;
  }
  if (first == last) return NumberStatus::NotANumber;
  auto [end, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range)
    return end == last && belowOne(first, last) ? NumberStatus::TooSmall : NumberStatus::NotFinite;
  if (ec != std::errc() || end != last) return NumberStatus::NotANumber;
  if (!std::isfinite(value)) return NumberStatus::NotFinite;
  return NumberStatus::Ok;
}

}  // namespace vkrt
