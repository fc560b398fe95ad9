#include "checker/dot_overlay.hpp"

#include <algorithm>

namespace gmr::checker {
using namespace gmr::rewrite;
using namespace gmr::draw;

namespace {

void add(std::vector<DotHighlight>& out, std::optional<graph::Side> side,
         const std::vector<std::string>& nodes, const std::vector<std::string>& path,
         const std::string& code, const std::string& message, bool error) {
  for (const auto& v : nodes.empty() ? path : nodes) out.push_back({side, v, code, message, error});
}

// The side of a diagnostic; without one, the arcs' tags ("a -2-> c (L)") tell it when they agree.
std::optional<graph::Side> side_of(const Diagnostic& d) {
  if (d.side || d.arcs.empty()) return d.side;
  auto on = [&](const char* tag) {
    return std::all_of(d.arcs.begin(), d.arcs.end(),
                       [&](const std::string& a) { return a.ends_with(tag); });
  };
  if (on("(L)")) return graph::Side::L;
  if (on("(R)")) return graph::Side::R;
  return std::nullopt;
}

}  // namespace

std::vector<DotHighlight> dot_highlights(const CheckReport& r) {
  std::vector<DotHighlight> out;
  for (const auto& d : r.diagnostics)
    if (d.severity != Severity::Note)
      add(out, side_of(d), d.nodes, d.path, d.code, d.message, d.severity == Severity::Error);
  return out;
}

}  // namespace gmr::checker
