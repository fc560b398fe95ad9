// Exhaustiveness of a pattern set (Damiand & Nivoliers 2022 §6.4): duplicates are patterns whose
// boundaries share a signature (in the store's mode); missing configurations are the generated
// configurations whose cell signature is in no pattern's key. Configurations are grouped into
// classes by their key (equal keys = isomorphic cells, Theorem 1).
#pragma once
#include <vector>

#include "model/replace/configurations.hpp"
#include "model/replace/pattern_store.hpp"

namespace gmr::replace {

struct CoverageReport {
  Mode mode = Mode::Unoriented;
  size_t configurations = 0;
  size_t classes = 0;                           // distinct cell signatures among configurations
  std::vector<std::vector<size_t>> duplicates;  // groups of patterns sharing a key
  std::vector<size_t> covering;                 // per pattern: configurations it matches
  std::vector<size_t> missing;                  // one configuration (index) per uncovered class
  size_t missing_configurations = 0;
  bool complete() const { return missing.empty(); }
};

CoverageReport check_coverage(const PatternStore& store, const ConfigurationSet& set);

}  // namespace gmr::replace
