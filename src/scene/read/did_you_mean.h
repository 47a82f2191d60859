// "Did you mean ...?" suggestions for misspelt keys, types and names.
//
// Distances are optimal-string-alignment edit distances (insertion, deletion, substitution and
// transposition of neighbours each cost 1) between lower-cased strings, so "raduis", "Radius" and
// "radus" all suggest "radius".
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace candela {

// Edit distance between a and b, as described above (case-sensitive).
size_t editDistance(const std::string& a, const std::string& b);

// The candidate closest to `word`, or "" when none is close enough to be a likely typo: a
// case-insensitive match, or a distance of at most 1 (words shorter than 5 characters) or 2.
// Ties go to the earlier candidate.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

// The names a file offers, for an error that says none is the one asked for: the first `shown`
// quoted and separated by commas, and how many more there are.
std::string quotedNames(const std::vector<std::string>& names, size_t shown = 20);

}  // namespace candela
