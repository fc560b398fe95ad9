#include "model/core/orbit_type.hpp"

#include <cctype>

#include "model/core/error.hpp"

namespace gmr {

OrbitType OrbitType::parse(std::string_view text) {
  size_t p = 0;
  auto skip = [&] {
    while (p < text.size() && std::isspace(static_cast<unsigned char>(text[p]))) ++p;
  };
  auto fail = [&](const std::string& what) -> Error {
    return Error(ErrorCode::Parse, "bad orbit type \"" + std::string(text) + "\": " + what,
                 "character " + std::to_string(p));
  };
  skip();
  if (p >= text.size() || text[p] != '<') throw fail("expected '<'");
  ++p;
  std::vector<int> dims;
  skip();
  if (p < text.size() && text[p] == '>') {
    ++p;
  } else {
    for (;;) {
      skip();
      if (p < text.size() && text[p] == '_') {
        dims.push_back(kHole);
        ++p;
      } else if (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) {
        int v = 0;
        while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) {
          v = v * 10 + (text[p] - '0');
          if (v > kMaxDim) throw fail("dimension above " + std::to_string(kMaxDim));
          ++p;
        }
        dims.push_back(v);
      } else {
        throw fail("expected a dimension or '_'");
      }
      skip();
      if (p < text.size() && text[p] == ',') {
        ++p;
        continue;
      }
      if (p < text.size() && text[p] == '>') {
        ++p;
        break;
      }
      throw fail("expected ',' or '>'");
    }
  }
  skip();
  if (p != text.size()) throw fail("trailing characters");
  return OrbitType(std::move(dims));
}

OrbitType OrbitType::cell(int n, int i) {
  std::vector<int> dims;
  for (int d = 0; d <= n; ++d)
    if (d != i) dims.push_back(d);
  return OrbitType(std::move(dims));
}

OrbitType OrbitType::range(int lo, int hi) {
  std::vector<int> dims;
  for (int d = lo; d <= hi; ++d) dims.push_back(d);
  return OrbitType(std::move(dims));
}

bool OrbitType::has_hole() const {
  for (int d : dims_)
    if (d == kHole) return true;
  return false;
}

DimMask OrbitType::mask() const {
  DimMask m = 0;
  for (int d : dims_)
    if (d != kHole) m |= DimMask(1) << d;
  return m;
}

bool OrbitType::contains(int dim) const {
  for (int d : dims_)
    if (d == dim) return true;
  return false;
}

std::string OrbitType::str() const {
  std::string s = "<";
  for (size_t p = 0; p < dims_.size(); ++p) {
    if (p) s += ',';
    s += dims_[p] == kHole ? std::string("_") : std::to_string(dims_[p]);
  }
  return s + ">";
}

}  // namespace gmr
