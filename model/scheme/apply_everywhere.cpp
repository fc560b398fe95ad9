#include "model/scheme/apply_everywhere.hpp"

#include <string>

#include "model/core/error.hpp"
#include "model/scheme/component_rewrite.hpp"

namespace gmr::scheme {

size_t EverywhereApplication::darts_added() const {
  size_t n = 0;
  for (const auto& a : applications) n += a.darts_added;
  return n;
}

size_t EverywhereApplication::darts_deleted() const {
  size_t n = 0;
  for (const auto& a : applications) n += a.darts_deleted;
  return n;
}

namespace {

// The contract of the header, one scheme::apply per visited dart.
EverywhereApplication apply_at_each_dart(const SchemeEngine& engine, Map& g, bool keep_tables,
                                         ApplicationObserver* observer) {
  const RuleScheme& s = engine.scheme();
  if (s.hooks.size() != 1)
    throw Error(ErrorCode::Usage,
                "applying at every dart needs a scheme with one hook; \"" + s.name + "\" has " +
                    std::to_string(s.hooks.size()),
                "scheme " + s.name);
  EverywhereApplication out;
  const std::vector<Dart> darts = g.darts();
  std::vector<bool> used(g.capacity(), false);
  for (Dart d : darts) {
    if (used[d] || !g.alive(d)) continue;
    SchemeApplication app = scheme::apply(engine, g, {d}, observer);
    if (!app) {
      if (out.applications.empty()) out.last_failure = std::move(app);
      continue;
    }
    for (Dart x : app.match)
      if (x < used.size()) used[x] = true;
    out.hooks.push_back(d);
    if (!keep_tables) {
      app.orbit.clear();
      app.match.clear();
      app.comatch.clear();
    }
    out.applications.push_back(std::move(app));
  }
  if (!out.applications.empty()) out.last_failure = SchemeApplication{};
  return out;
}

}  // namespace

EverywhereApplication apply_everywhere(const SchemeEngine& engine, Map& g,
                                       const EverywhereOptions& options) {
  ApplicationObserver* const observer = options.observer;
  auto* const by_components = dynamic_cast<ComponentObserver*>(observer);
  switch (options.path) {
    case EverywherePath::Automatic:
      if ((observer == nullptr || by_components != nullptr) && rewrites_whole_components(engine, g))
        return detail::apply_by_components(engine, g, options.keep_tables, by_components);
      break;
    case EverywherePath::AtEachDart:
      break;
    case EverywherePath::ByComponents:
      if (observer != nullptr && by_components == nullptr)
        throw Error(ErrorCode::Usage, "the observer does not observe whole components",
                    "scheme " + engine.scheme().name);
      return detail::apply_by_components(engine, g, options.keep_tables, by_components);
  }
  return apply_at_each_dart(engine, g, options.keep_tables, observer);
}

}  // namespace gmr::scheme
