// Edit distance and the nearest name (host/util/suggest.h).
#include "util/suggest.h"

#include <algorithm>
#include <vector>

namespace vkrt {
namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// The distance a word of `length` characters may be from the name it was meant to be.
std::size_t allowedDistance(std::size_t length) { return std::min<std::size_t>(length <= 4 ? 1 : 2, length - 1); }

// Whether `name` begins with `word` (any case): a word cut short names it.
bool startsWith(std::string_view name, std::string_view word) {
  if (name.size() < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (lower(name[i]) != lower(word[i])) return false;
  return true;
}

}  // namespace

std::size_t editDistance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic programme: d[i][j] is the distance between a's first i
  // characters and b's first j.
  const std::size_t m = b.size();
  std::vector<std::size_t> before(m + 1), previous(m + 1), current(m + 1);
  for (std::size_t j = 0; j <= m; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const bool same = lower(a[i - 1]) == lower(b[j - 1]);
      std::size_t d = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
        d = std::min(d, before[j - 2] + 1);   // two adjacent characters swapped
      current[j] = d;
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[m];
}

std::optional<std::string_view> closestMatch(std::string_view word, std::span<const std::string_view> candidates) {
  if (word.empty()) return std::nullopt;
  const std::size_t allowed = allowedDistance(word.size());
  std::optional<std::string_view> best;
  std::size_t bestDistance = allowed + 1;
  for (std::string_view c : candidates) {
    // The lengths alone bound the distance from below: a long token costs no full comparison.
    const std::size_t lengthGap = c.size() > word.size() ? c.size() - word.size() : word.size() - c.size();
    if (lengthGap > bestDistance) continue;
    const std::size_t d = editDistance(word, c);
    // Of two names as near, the one the word begins ("--max-bias-" is --max-bias-z cut short).
    if (d < bestDistance || (d == bestDistance && best && startsWith(c, word) && !startsWith(*best, word))) {
      best = c;
      bestDistance = d;
    }
  }
  return best;
}

std::string didYouMean(std::string_view word, std::span<const std::string_view> candidates, std::string_view prefix) {
  std::optional<std::string_view> match = closestMatch(word, candidates);
  if (!match) return "";
  return "; did you mean '" + std::string(prefix) + std::string(*match) + "'?";
}

}  // namespace vkrt
