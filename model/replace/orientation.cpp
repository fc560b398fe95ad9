#include "model/replace/orientation.hpp"

#include "model/core/error.hpp"

namespace gmr::replace {

std::vector<uint8_t> orientation_classes(const Map& g) {
  constexpr uint8_t kUnset = 2;
  std::vector<uint8_t> colour(g.capacity(), kUnset);
  std::vector<Dart> stack;
  g.for_each_dart([&](Dart d) {
    if (colour[d] != kUnset) return;
    colour[d] = 1;
    stack.push_back(d);
    while (!stack.empty()) {
      const Dart x = stack.back();
      stack.pop_back();
      for (int i = g.lowest_dim(); i <= g.dimension(); ++i) {
        const Dart y = g.alpha(i, x);
        if (y == x) continue;
        if (colour[y] == kUnset) {
          colour[y] = static_cast<uint8_t>(1 - colour[x]);
          stack.push_back(y);
        } else if (colour[y] == colour[x]) {
          throw Error(ErrorCode::InvalidMap, "the oriented mode needs an orientable map",
                      "dart " + std::to_string(x));
        }
      }
    }
  });
  for (auto& c : colour)
    if (c == kUnset) c = 0;
  return colour;
}

}  // namespace gmr::replace
