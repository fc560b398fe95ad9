#include "checker/dot_overlay.hpp"

namespace gmr {

namespace {

void add(std::vector<DotHighlight>& out, const std::string& side, const std::vector<std::string>& nodes,
         const std::vector<std::string>& path, const std::string& code, const std::string& message, bool error) {
  for (const auto& v : nodes.empty() ? path : nodes) out.push_back({side, v, code, message, error});
}

}  // namespace

std::vector<DotHighlight> dot_highlights(const CheckReport& r) {
  std::vector<DotHighlight> out;
  for (const auto& d : r.diagnostics)
    if (d.severity == Severity::Error) add(out, d.side, d.nodes, d.path, d.code, d.message, true);
  return out;
}

std::vector<DotHighlight> dot_highlights(const SchemeCheckReport& r) {
  std::vector<DotHighlight> out;
  for (const auto& d : r.diagnostics)
    if (d.severity != SchemeSeverity::Note)
      add(out, d.side, d.nodes, d.path, d.code, d.message, d.severity == SchemeSeverity::Error);
  return out;
}

}  // namespace gmr
