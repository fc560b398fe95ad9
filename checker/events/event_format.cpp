#include "checker/events/event_format.hpp"

#include <sstream>

namespace gmr::events {
using nlohmann::ordered_json;
using scheme::RuleScheme;

namespace {

std::vector<std::string> orbit_names(const RuleScheme& s, const OrbitTypeEvents& t, Side side,
                                     const std::vector<uint32_t>& cs) {
  std::vector<std::string> out;
  for (uint32_t c : cs) out.push_back(pattern_orbit_name(s, t, side, c));
  return out;
}

std::string join(const std::vector<std::string>& xs, const std::string& sep) {
  std::string s;
  for (size_t k = 0; k < xs.size(); ++k) s += (k ? sep : "") + xs[k];
  return s;
}

std::string pair_text(const RuleScheme& s, const InstancePair& p) {
  const std::string b2 = p.position < 0 ? "b" : "b+" + std::to_string(p.position + 1);
  return "m(b," + s.left.nodes[p.a].name + "), m(" + b2 + "," + s.left.nodes[p.b].name + ")";
}

ordered_json pattern_orbits_json(const RuleScheme& s, const PatternOrbits& p) {
  const auto& side = p.side == Side::L ? s.left : s.right;
  ordered_json out = ordered_json::array();
  for (uint32_t c = 0; c < p.size(); ++c) {
    ordered_json nodes = ordered_json::array();
    for (uint32_t m : p.nodes[c]) nodes.push_back(side.nodes[m].name);
    out.push_back({{"nodes", nodes}, {"complete", static_cast<bool>(p.complete[c])}});
  }
  return out;
}

}  // namespace

std::string describe(const RuleScheme& s, const OrbitTypeEvents& t, const PatternEvent& e) {
  std::string text = to_string(e.kind);
  if (!e.positions.empty()) {
    std::vector<std::string> ks;
    for (uint32_t k : e.positions) ks.push_back(std::to_string(k + 1));
    text += " along " + join(ks, ",");
  }
  const auto l = orbit_names(s, t, Side::L, e.left), r = orbit_names(s, t, Side::R, e.right);
  switch (e.kind) {
    case PatternEventKind::Creation:
      text += " of " + join(r, ", ");
      break;
    case PatternEventKind::Deletion:
      text += " of " + join(l, ", ");
      break;
    default:
      text += " of " + join(l, ", ") + " -> " + join(r, ", ");
      break;
  }
  text += std::string(", ") + to_string(e.certainty);
  if (e.certainty == Certainty::Possible) {
    std::vector<std::string> ps;
    for (const auto& p : e.pairs) ps.push_back(pair_text(s, p));
    text += ": compare " + join(ps, "; ") + (is_split(e.kind) ? " on H" : " on G");
  }
  return text;
}

ordered_json static_events_to_json(const RuleScheme& s, const StaticEvents& st) {
  ordered_json j;
  j["format"] = kEventsFormat;
  j["version"] = kEventsVersion;
  j["kind"] = "static";
  j["rule"] = s.name;
  j["dimension"] = st.dimension;
  ordered_json orbits = ordered_json::array();
  for (const auto& t : st.orbits) {
    ordered_json o;
    o["orbit"] = t.orbit.str();
    o["left"] = pattern_orbits_json(s, t.left);
    o["right"] = pattern_orbits_json(s, t.right);
    ordered_json evs = ordered_json::array();
    for (const auto& e : t.events) {
      ordered_json ej;
      ej["event"] = to_string(e.kind);
      ej["certainty"] = to_string(e.certainty);
      ej["left"] = orbit_names(s, t, Side::L, e.left);
      ej["right"] = orbit_names(s, t, Side::R, e.right);
      if (!e.positions.empty()) {
        ordered_json ks = ordered_json::array();
        for (uint32_t k : e.positions) ks.push_back(k + 1);
        ej["positions"] = ks;
      }
      if (is_split(e.kind) || is_merge(e.kind)) {
        ej["checked_on"] = is_split(e.kind) ? "H" : "G";
        ordered_json ps = ordered_json::array();
        for (const auto& p : e.pairs) {
          ordered_json pj = {{"a", s.left.nodes[p.a].name}, {"b", s.left.nodes[p.b].name}};
          if (p.position >= 0) pj["position"] = p.position + 1;
          ps.push_back(pj);
        }
        ej["pairs"] = ps;
      }
      evs.push_back(ej);
    }
    o["events"] = evs;
    orbits.push_back(o);
  }
  j["orbits"] = orbits;
  return j;
}

std::string static_events_to_text(const RuleScheme& s, const StaticEvents& st) {
  std::ostringstream os;
  os << s.name << " (n = " << s.dimension << ", " << s.orbit.str() << "): " << st.orbits.size()
     << " orbit type" << (st.orbits.size() == 1 ? "" : "s") << "\n";
  for (const auto& t : st.orbits) {
    os << t.orbit.str() << "  pattern orbits";
    for (const PatternOrbits* p : {&t.left, &t.right}) {
      const auto& side = p->side == Side::L ? s.left : s.right;
      os << (p->side == Side::L ? "  L:" : "  R:");
      for (uint32_t c = 0; c < p->size(); ++c) {
        std::vector<std::string> names;
        for (uint32_t m : p->nodes[c]) names.push_back(side.nodes[m].name);
        os << " {" << join(names, ",") << "}" << (p->complete[c] ? "" : "*");
      }
    }
    os << "  (* incomplete)\n";
    for (const auto& e : t.events) os << "  " << describe(s, t, e) << "\n";
  }
  return os.str();
}

ordered_json event_log_to_json(const RuleScheme& s, const StaticEvents& st, const EventLog& log) {
  ordered_json j;
  j["format"] = kEventsFormat;
  j["version"] = kEventsVersion;
  j["kind"] = "log";
  j["rule"] = log.rule;
  j["hooks"] = log.hooks;
  ordered_json orbits = ordered_json::array();
  for (size_t t = 0; t < log.orbits.size(); ++t) {
    const auto& l = log.orbits[t];
    ordered_json o;
    o["orbit"] = l.orbit.str();
    o["traversed"] = l.traversed;
    ordered_json evs = ordered_json::array();
    for (const auto& e : l.events)
      evs.push_back({{"event", to_string(e.kind)},
                     {"status", to_string(e.status)},
                     {"before", e.before.vector()},
                     {"after", e.after.vector()},
                     {"text", e.describe()}});
    o["events"] = evs;
    ordered_json cs = ordered_json::array();
    for (const auto& c : l.checks)
      cs.push_back({{"pattern_event", describe(s, st.orbits[t], st.orbits[t].events[c.event])},
                    {"map", std::string(1, c.map)},
                    {"darts", {c.a, c.b}},
                    {"different", c.different}});
    o["checks"] = cs;
    orbits.push_back(o);
  }
  j["orbits"] = orbits;
  return j;
}

ordered_json event_logs_to_json(const RuleScheme& s, const StaticEvents& st,
                                const std::vector<EventLog>& logs) {
  ordered_json j;
  j["format"] = kEventsFormat;
  j["version"] = kEventsVersion;
  j["kind"] = "log-set";
  j["rule"] = s.name;
  ordered_json apps = ordered_json::array();
  for (const EventLog& log : logs) apps.push_back(event_log_to_json(s, st, log));
  j["applications"] = apps;
  return j;
}

std::string event_log_to_text(const EventLog& log) {
  std::ostringstream os;
  for (const auto& l : log.orbits) {
    size_t confirmed = 0;
    for (const auto& c : l.checks) confirmed += c.different;
    os << l.orbit.str() << " (" << l.checks.size() << " pair" << (l.checks.size() == 1 ? "" : "s")
       << " checked, " << confirmed << " different; " << l.traversed << " darts traversed)\n";
    for (const auto& e : l.events)
      os << "  " << e.describe() << " [" << to_string(e.status) << "]\n";
  }
  return os.str();
}

}  // namespace gmr::events
