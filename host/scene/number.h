// Number parsing for scene files: decimals with an optional sign ('+1'), exponents ('1e-3'),
// no locale, no allocation. Rejects NaN and infinity, and numbers beyond a double's range:
// too large (1e400: NotFinite, it would be infinite) or too small (1e-400: TooSmall, below
// the smallest positive double, about 4.9e-324, it would be 0). Subnormal numbers (1e-310)
// are accepted as the nearest double.
#pragma once

#include <string_view>

namespace vkrt {

enum class NumberStatus { Ok, NotANumber, NotFinite, TooSmall };

// Parses all of `token` as a finite double.
NumberStatus parseNumber(std::string_view token, double& value);

}  // namespace vkrt
