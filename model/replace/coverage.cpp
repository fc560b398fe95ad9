#include "model/replace/coverage.hpp"

#include <unordered_map>

#include "model/replace/orientation.hpp"

namespace gmr::replace {

CoverageReport check_coverage(const PatternStore& store, const ConfigurationSet& set) {
  CoverageReport r;
  r.mode = store.mode();
  r.configurations = set.configurations.size();
  r.duplicates = store.duplicates();
  r.covering.assign(store.patterns().size(), 0);
  std::unordered_map<Word, size_t, WordHash> first_of_class;
  for (size_t i = 0; i < set.configurations.size(); ++i) {
    const Configuration& c = set.configurations[i];
    std::vector<uint8_t> positive;
    if (store.mode() == Mode::Oriented) positive = orientation_classes(c.map.map);
    const Word key = store_key(cell_boundary(c.map.map, set.cell_dim, c.cell, c.map.flag, positive),
                               set.cell_dim, store.mode());
    const bool new_class = first_of_class.emplace(key, i).second;
    if (const auto* hits = store.find(key)) {
      for (const StoreEntry& e : *hits) ++r.covering[e.pattern];
    } else {
      ++r.missing_configurations;
      if (new_class) r.missing.push_back(i);
    }
  }
  r.classes = first_of_class.size();
  return r;
}

}  // namespace gmr::replace
