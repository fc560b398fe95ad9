#include "checker/dot_overlay.hpp"

#include <algorithm>

namespace gmr::checker {
using namespace gmr::rewrite;
using namespace gmr::draw;

namespace {

void add(std::vector<DotHighlight>& out, const std::string& side, const std::vector<std::string>& nodes,
         const std::vector<std::string>& path, const std::string& code, const std::string& message, bool error) {
  for (const auto& v : nodes.empty() ? path : nodes) out.push_back({side, v, code, message, error});
}

}  // namespace

std::vector<DotHighlight> dot_highlights(const CheckReport& r) {
  std::vector<DotHighlight> out;
  for (const auto& d : r.diagnostics) {
    if (d.severity != Severity::Error) continue;
    // Without a side, the arcs' tags ("a -2-> c (L)") tell it when they agree.
    std::string side = d.side_str();
    if (side.empty() && !d.arcs.empty()) {
      auto on = [&](const char* tag) {
        return std::all_of(d.arcs.begin(), d.arcs.end(), [&](const std::string& a) { return a.ends_with(tag); });
      };
      side = on("(L)") ? "L" : on("(R)") ? "R" : "";
    }
    add(out, side, d.nodes, d.path, d.code, d.message, true);
  }
  return out;
}

std::vector<DotHighlight> dot_highlights(const SchemeCheckReport& r) {
  std::vector<DotHighlight> out;
  for (const auto& d : r.diagnostics)
    if (d.severity != Severity::Note)
      add(out, d.side_str(), d.nodes, d.path, d.code, d.message, d.severity == Severity::Error);
  return out;
}

}  // namespace gmr::checker
