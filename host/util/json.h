// JSON string literals, for every report vkrt writes as JSON (diff --json, --stats --json,
// the grading report's summary).
#pragma once

#include <string>

namespace vkrt {

// `s` as a JSON string literal (valid JSON whatever its bytes: each byte that is not part of
// well-formed UTF-8 becomes U+FFFD).
std::string jsonQuoted(const std::string& s);

}  // namespace vkrt
