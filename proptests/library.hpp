// The scheme library used by the property tests: the standard operations of tools/data/rules and
// the 50 rules of the Jerboa fixture (tools/data/jerboa/JerboaTrackingOrbit.jme), each with the
// scheme checker's verdict. Schemes the engine cannot apply (malformed, or breaking I_S) are left
// out. Loaded once from $GMR_SOURCE_DIR (set by CTest).
#pragma once
#include <memory>
#include <vector>

#include "model/scheme/rule_scheme.hpp"
#include "model/scheme/scheme_engine.hpp"

namespace gmr::prop {
using scheme::RuleScheme;
using scheme::SchemeEngine;

struct LibraryScheme {
  RuleScheme scheme;
  bool accepted = false;                       // check_scheme(scheme).ok()
  bool standard = false;                       // from tools/data/rules (not the Jerboa fixture)
  std::shared_ptr<const SchemeEngine> engine;  // prepared once
};

const std::vector<LibraryScheme>& scheme_library();
// Indices of the library schemes of dimension n (accepted ones only when accepted_only).
std::vector<size_t> library_of_dim(int n, bool accepted_only);

}  // namespace gmr::prop
