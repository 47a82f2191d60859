// Edit-distance suggestions; see did_you_mean.h.
#include "scene/read/did_you_mean.h"

#include <algorithm>
#include <cctype>

namespace candela {

size_t editDistance(const std::string& a, const std::string& b) {
  // Three rolling rows of the dynamic-programming table: the transposition rule looks two back.
  std::vector<size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[b.size()];
}

static std::string lowerCase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
  // A typo of a name is about as long as the name: longer words are never compared, and a
  // candidate whose length differs by more than the threshold cannot be within it.
  constexpr size_t kLongestCompared = 64;
  if (word.size() > kLongestCompared) return "";
  const std::string lowered = lowerCase(word);
  const size_t threshold = lowered.size() < 5 ? 1 : 2;
  std::string best;
  size_t bestDistance = threshold + 1;
  for (const std::string& candidate : candidates) {
    const size_t gap = candidate.size() > lowered.size() ? candidate.size() - lowered.size()
                                                         : lowered.size() - candidate.size();
    if (gap > threshold) continue;
    const size_t distance = editDistance(lowered, lowerCase(candidate));
    if (distance < bestDistance) {
      best = candidate;
      bestDistance = distance;
    }
  }
  return best;
}

std::string quotedNames(const std::vector<std::string>& names, size_t shown) {
  std::string list;
  for (size_t i = 0; i < names.size() && i < shown; ++i)
    list += (i == 0 ? "\"" : ", \"") + names[i] + "\"";
  if (names.size() > shown) list += " and " + std::to_string(names.size() - shown) + " more";
  return list;
}

}  // namespace candela
