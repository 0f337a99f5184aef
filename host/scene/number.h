// Number parsing for scene files: decimals with an optional sign ('+1'), exponents ('1e-3'),
// no locale, no allocation. Rejects NaN and infinity.
#pragma once

#include <string_view>

namespace vkrt {

enum class NumberStatus { Ok, NotANumber, NotFinite };

// Parses all of `token` as a finite double.
NumberStatus parseNumber(std::string_view token, double& value);

}  // namespace vkrt
