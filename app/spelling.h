#pragma once
/// @file spelling.h
/// "Did you mean ...?": the closest of a list of known names to a misspelt one.

#include <optional>
#include <string>
#include <vector>

namespace impulse2d::demos {

/// Edit distance (insertions, deletions, substitutions, adjacent swaps) between `a` and `b`.
int edit_distance(const std::string& a, const std::string& b);

/// The name in `known` closest to `word` when it is close enough to be a likely misspelling
/// (at most 1 edit for words up to 4 characters, else up to a third of the word's length, at
/// most 3), or a name that `word` is a prefix of; the first such name on a tie. Nothing
/// otherwise.
std::optional<std::string> closest_spelling(const std::string& word,
                                            const std::vector<std::string>& known);

}  // namespace impulse2d::demos
