// "Did you mean" for every name a person types: flags, commands, techniques, parameters, scene
// keys, channels. One edit distance (Damerau-Levenshtein, optimal string alignment) for all.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra {

// Edits (insert, delete, substitute, swap two neighbours) that turn A into B.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to TYPED when it is close enough to be a typo (at most a third of its
// length, at least 1, at most 3 edits; ties: the first), else "".
std::string nearestName(std::string_view typed, std::span<const std::string_view> candidates);
std::string nearestName(std::string_view typed, const std::vector<std::string>& candidates);

// " (did you mean 'X'?)" for nearestName, or "" when nothing is near.
std::string didYouMean(std::string_view typed, std::span<const std::string_view> candidates);
std::string didYouMean(std::string_view typed, const std::vector<std::string>& candidates);

}  // namespace penumbra
