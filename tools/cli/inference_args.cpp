#include "tools/cli/inference_args.hpp"

#include <sstream>

#include "model/core/error.hpp"

namespace gmr::cli {

using namespace gmr::inference;

OrbitType parse_orbit_option(const std::string& text, const std::string& option) {
  OrbitType o;
  try {
    o = OrbitType::parse(text);
  } catch (const Error& e) {
    throw Error(ErrorCode::Usage, e.message(), option);
  }
  if (o.has_hole()) throw Error(ErrorCode::Usage, "an inference orbit type has no `_`", option);
  return o;
}

DimMask parse_dimension_list(const std::string& text, int n, const std::string& option) {
  DimMask m = 0;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    size_t used = 0;
    int d = -1;
    try {
      d = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || d < 0 || d > n)
      throw Error(ErrorCode::Usage,
                  "\"" + item + "\" is not a dimension in 0.." + std::to_string(n), option);
    m |= DimMask(1) << d;
  }
  return m;
}

}  // namespace gmr::cli
