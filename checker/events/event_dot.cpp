#include "checker/events/event_dot.hpp"

#include "checker/events/event_format.hpp"

namespace gmr::events {

namespace {
std::string code(const PatternEvent& e) {
  std::string c;
  switch (e.kind) {
    case PatternEventKind::Creation:
      c = "C";
      break;
    case PatternEventKind::Deletion:
      c = "D";
      break;
    case PatternEventKind::ExplicitSplit:
    case PatternEventKind::ImplicitSplit:
      c = "S";
      break;
    case PatternEventKind::ExplicitMerge:
    case PatternEventKind::ImplicitMerge:
      c = "M";
      break;
    case PatternEventKind::Modification:
      c = "mod";
      break;
    case PatternEventKind::NonModification:
      break;
  }
  for (uint32_t k : e.positions) c += std::to_string(k + 1);
  if (e.certainty == Certainty::Possible) c += "?";
  return c;
}
}  // namespace

std::vector<draw::DotHighlight> dot_highlights(const scheme::RuleScheme& s,
                                               const OrbitTypeEvents& t) {
  std::vector<draw::DotHighlight> out;
  for (const auto& e : t.events) {
    if (e.kind == PatternEventKind::NonModification) continue;
    const std::string text = t.orbit.str() + " " + describe(s, t, e);
    const bool certain = e.certainty == Certainty::Certain;
    // Creations on R only; deletions, splits, merges and modifications on both sides.
    if (e.kind != PatternEventKind::Creation)
      for (uint32_t c : e.left)
        for (uint32_t m : t.left.nodes[c])
          out.push_back({graph::Side::L, s.left.nodes[m].name, code(e), text, certain});
    if (e.kind != PatternEventKind::Deletion)
      for (uint32_t c : e.right)
        for (uint32_t m : t.right.nodes[c])
          out.push_back({graph::Side::R, s.right.nodes[m].name, code(e), text, certain});
  }
  return out;
}

}  // namespace gmr::events
