// "Did you mean ...?": the name nearest to a mistyped word, for the command line (subcommands,
// options) and the scene parser (commands). Depends on nothing.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace vkrt {

// The edit distance between `a` and `b`, ignoring ASCII case: the fewest insertions,
// deletions, substitutions and swaps of two adjacent characters that turn one into the other
// (optimal string alignment: `mrege` is 1 from `merge`, `sphre` 1 from `sphere`).
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to `word` when it is near enough to be what was meant: at most 1 edit
// for a word of up to 4 characters, 2 for a longer one, and fewer edits than the word has
// characters. Of candidates equally near, the first. Nothing when none is near enough.
std::optional<std::string_view> closestMatch(std::string_view word, std::span<const std::string_view> candidates);

// "; did you mean 'NAME'?" with `prefix` before the closest match, or "" when there is none.
std::string didYouMean(std::string_view word, std::span<const std::string_view> candidates,
                       std::string_view prefix = "");

}  // namespace vkrt
