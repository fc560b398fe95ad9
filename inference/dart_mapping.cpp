#include "inference/dart_mapping.hpp"

#include <algorithm>
#include <numeric>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/map_io/json_reader.hpp"
#include "model/map_io/json_writer.hpp"
#include "model/map_io/read_file.hpp"

namespace gmr::inference {

using namespace gmr::io;

namespace {
constexpr const char* kFormat = "gmr.mapping";
constexpr int kVersion = 1;

Dart read_dart(const JsonAt& at) { return static_cast<Dart>(at.as_int(0, UINT32_MAX - 1)); }

OrbitType read_orbit(const JsonAt& at) {
  try {
    return OrbitType::parse(at.as_string());
  } catch (const Error& e) {
    if (e.code() != ErrorCode::Parse) throw;
    at.fail(e.message());
  }
}
}  // namespace

DartMapping identity_mapping(const Map& before, const Map& after) {
  DartMapping m;
  before.for_each_dart([&](Dart d) {
    if (after.alive(d)) m.pairs.emplace_back(d, d);
  });
  return m;
}

DartMapping parse_mapping(std::string_view text, const std::string& source) {
  const nlohmann::json doc = parse_json(text, source);
  const JsonAt root(doc, source);
  root.check_header(kFormat, kVersion);
  root.allow_only({"format", "version", "pairs", "orbits", "before_selection", "after_selection"});
  DartMapping m;
  if (auto pairs = root.get("pairs")) {
    for (size_t k = 0; k < pairs->array_size(); ++k) {
      const JsonAt p = (*pairs)[k];
      if (p.array_size() != 2) p.fail("a pair is [before dart, after dart]");
      m.pairs.emplace_back(read_dart(p[0]), read_dart(p[1]));
    }
  }
  if (auto orbits = root.get("orbits")) {
    for (size_t k = 0; k < orbits->array_size(); ++k) {
      const JsonAt o = (*orbits)[k];
      o.require_object();
      o.allow_only({"before", "after", "orbit", "after_orbit"});
      OrbitPair op;
      op.before = read_dart(o["before"]);
      op.after = read_dart(o["after"]);
      op.orbit = read_orbit(o["orbit"]);
      op.after_orbit = o.has("after_orbit") ? read_orbit(o["after_orbit"]) : op.orbit;
      if (op.orbit.has_hole() || op.after_orbit.has_hole())
        o.fail("an orbit pair uses orbit types without `_`");
      if (op.orbit.size() != op.after_orbit.size())
        o["after_orbit"].fail(
            "\"orbit\" and \"after_orbit\" must have the same size (positional relabeling)");
      m.orbits.push_back(op);
    }
  }
  for (const char* key : {"before_selection", "after_selection"})
    if (auto sel = root.get(key)) {
      std::vector<Dart> darts;
      for (size_t k = 0; k < sel->array_size(); ++k) darts.push_back(read_dart((*sel)[k]));
      (std::string(key) == "before_selection" ? m.before_selection : m.after_selection) =
          std::move(darts);
    }
  return m;
}

DartMapping read_mapping_file(const std::filesystem::path& path) {
  return parse_mapping(read_text_file(path), path.string());
}

std::string mapping_to_json_text(const DartMapping& m) {
  nlohmann::ordered_json j;
  j["format"] = kFormat;
  j["version"] = kVersion;
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
  for (auto [g, h] : m.pairs) pairs.push_back({g, h});
  j["pairs"] = pairs;
  if (!m.orbits.empty()) {
    nlohmann::ordered_json orbits = nlohmann::ordered_json::array();
    for (const auto& o : m.orbits)
      orbits.push_back({{"before", o.before},
                        {"after", o.after},
                        {"orbit", o.orbit.str()},
                        {"after_orbit", o.after_orbit.str()}});
    j["orbits"] = orbits;
  }
  if (m.before_selection) j["before_selection"] = *m.before_selection;
  if (m.after_selection) j["after_selection"] = *m.after_selection;
  return dump_json(j);
}

std::vector<std::pair<Dart, Dart>> expand_mapping(const Map& before, const Map& after,
                                                  const DartMapping& m) {
  // Every pair with its source: pairs[s] for s < pairs.size(), else orbits[s - pairs.size()] (the
  // place named in errors, formatted only when one is raised).
  std::vector<std::pair<Dart, Dart>> out(m.pairs.begin(), m.pairs.end());
  std::vector<uint32_t> source(out.size());
  std::iota(source.begin(), source.end(), 0u);
  auto where = [&](size_t k) {
    const size_t s = source[k];
    return s < m.pairs.size() ? "pairs[" + std::to_string(s) + "]"
                              : "orbits[" + std::to_string(s - m.pairs.size()) + "]";
  };
  for (size_t k = 0; k < m.orbits.size(); ++k) {
    const OrbitPair& o = m.orbits[k];
    const std::string at = "orbits[" + std::to_string(k) + "]";
    if (!before.alive(o.before))
      throw Error(ErrorCode::Schema, "no dart " + std::to_string(o.before) + " in the before map",
                  at);
    if (!after.alive(o.after))
      throw Error(ErrorCode::Schema, "no dart " + std::to_string(o.after) + " in the after map",
                  at);
    require_orbit_type(before, o.orbit);
    require_orbit_type(after, o.after_orbit);
    const auto iso = orbit_isomorphism(before, o.orbit, o.before, after, o.after_orbit, o.after);
    if (!iso)
      throw Error(ErrorCode::Schema,
                  "the " + o.orbit.str() + "-orbit of before dart " + std::to_string(o.before) +
                      " and the " + o.after_orbit.str() + "-orbit of after dart " +
                      std::to_string(o.after) + " are not isomorphic (Alg. 5)",
                  at);
    for (auto p : *iso) {
      out.push_back(p);
      source.push_back(static_cast<uint32_t>(m.pairs.size() + k));
    }
  }
  std::vector<uint32_t> seen_b(before.capacity(), UINT32_MAX), seen_a(after.capacity(), UINT32_MAX);
  std::vector<std::pair<Dart, Dart>> uniq;
  uniq.reserve(out.size());
  for (size_t k = 0; k < out.size(); ++k) {
    const auto [g, h] = out[k];
    if (!before.alive(g))
      throw Error(ErrorCode::Schema, "no dart " + std::to_string(g) + " in the before map",
                  where(k));
    if (!after.alive(h))
      throw Error(ErrorCode::Schema, "no dart " + std::to_string(h) + " in the after map",
                  where(k));
    const bool sb = seen_b[g] != UINT32_MAX, sa = seen_a[h] != UINT32_MAX;
    if (sb && sa && seen_b[g] == h) continue;  // the same pair twice (e.g. overlapping orbit pairs)
    if (sb)
      throw Error(ErrorCode::Schema,
                  "before dart " + std::to_string(g) + " is mapped twice (to " +
                      std::to_string(seen_b[g]) + " and " + std::to_string(h) + ")",
                  where(k));
    if (sa)
      throw Error(ErrorCode::Schema,
                  "after dart " + std::to_string(h) + " is the image of two darts (" +
                      std::to_string(seen_a[h]) + " and " + std::to_string(g) + ")",
                  where(k));
    seen_b[g] = h;
    seen_a[h] = g;
    uniq.emplace_back(g, h);
  }
  std::sort(uniq.begin(), uniq.end());
  return uniq;
}

JointGraph joint_from_pair(const Map& before, const Map& after, const DartMapping& m,
                           JointIndex* index) {
  if (before.is_omap() || after.is_omap())
    throw Error(ErrorCode::Usage, "rule inference works on G-maps, not O-maps");
  if (before.dimension() != after.dimension())
    throw Error(ErrorCode::Usage, "the before map has dimension " +
                                      std::to_string(before.dimension()) + " and the after map " +
                                      std::to_string(after.dimension()));
  const auto pairs = expand_mapping(before, after, m);
  const int n = before.dimension();
  // Selected darts (all live darts without a selection).
  auto selected = [](const Map& g, const std::optional<std::vector<Dart>>& sel, const char* key) {
    std::vector<uint8_t> in(g.capacity(), 0);
    if (!sel) {
      g.for_each_dart([&](Dart d) { in[d] = 1; });
      return in;
    }
    for (size_t k = 0; k < sel->size(); ++k) {
      const Dart d = (*sel)[k];
      if (!g.alive(d))
        throw Error(ErrorCode::Schema, "no dart " + std::to_string(d) + " in the map",
                    std::string(key) + "[" + std::to_string(k) + "]");
      in[d] = 1;
    }
    return in;
  };
  const auto sb = selected(before, m.before_selection, "before_selection");
  const auto sa = selected(after, m.after_selection, "after_selection");
  for (auto [g, h] : pairs) {
    if (!sb[g])
      throw Error(ErrorCode::Schema,
                  "before dart " + std::to_string(g) + " is mapped but not selected",
                  "before_selection");
    if (!sa[h])
      throw Error(ErrorCode::Schema,
                  "after dart " + std::to_string(h) + " is mapped but not selected",
                  "after_selection");
  }
  JointGraph j(n);
  j.reserve(before.size() + after.size());
  std::vector<uint32_t> ib(before.capacity(), kUndefined), ia(after.capacity(), kUndefined);
  before.for_each_dart([&](Dart d) {
    if (sb[d]) ib[d] = j.add_dart(Side::L, d);
  });
  after.for_each_dart([&](Dart d) {
    if (sa[d]) ia[d] = j.add_dart(Side::R, d);
  });
  auto copy = [&](const Map& g, const std::vector<uint32_t>& idx) {
    g.for_each_dart([&](Dart d) {
      if (idx[d] == kUndefined) return;
      for (int i = 0; i <= n; ++i) {
        const Dart e = g.alpha(i, d);
        j.set_nbr(idx[d], i, e < idx.size() ? idx[e] : kUndefined);
      }
    });
  };
  copy(before, ib);
  copy(after, ia);
  for (auto [g, h] : pairs) j.link(kKappa, ib[g], ia[h]);
  if (index) {
    index->before = std::move(ib);
    index->after = std::move(ia);
  }
  return j;
}

}  // namespace gmr::inference
