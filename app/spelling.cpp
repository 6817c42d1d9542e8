/// @file spelling.cpp
#include "app/spelling.h"

#include <algorithm>

namespace impulse2d::demos {

int edit_distance(const std::string& a, const std::string& b) {
  // Optimal string alignment distance over three rows of the dynamic-programming table.
  const std::size_t n = b.size();
  std::vector<int> before(n + 1), previous(n + 1), current(n + 1);
  for (std::size_t j = 0; j <= n; ++j) previous[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= n; ++j) {
      const int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        current[j] = std::min(current[j], before[j - 2] + 1);
      }
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[n];
}

std::optional<std::string> closest_spelling(const std::string& word,
                                            const std::vector<std::string>& known) {
  if (word.empty()) return std::nullopt;
  const int allowed = word.size() <= 4 ? 1 : std::min(3, static_cast<int>(word.size()) / 3);
  std::optional<std::string> best;
  int best_distance = allowed + 1;
  for (const std::string& name : known) {
    const bool prefix = name.size() > word.size() && name.compare(0, word.size(), word) == 0;
    const int distance = prefix ? 1 : edit_distance(word, name);
    if (distance < best_distance) {
      best = name;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace impulse2d::demos
