#pragma once
// "Did you mean ...?": the valid name nearest to a misspelt one, for unknown keys, choices and
// material names. Near means a few edits away (a third of the word's length, at most three), so
// that a typo is named and an unrelated word is not.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace qs {

/// Optimal-string-alignment distance (Levenshtein plus adjacent transpositions), case-insensitive:
/// "porosty" is 1 from "porosity", "gimpp" 1 from "gimp", "fluidized" 1 from "fluidised".
std::size_t editDistance(std::string_view a, std::string_view b);

/// The candidate nearest to `word`, if it is near enough to be a plausible typo.
std::optional<std::string> nearest(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace qs
