// Jerboa .jme (XML): import every rule and validate each scheme's structure.
#include "model/rule_io/jme_import.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  const io::JmeModeler m = io::parse_jme(text, "fuzz.jme");
  for (const auto& s : m.rules) {
    try {
      s.validate_structure();
    } catch (const gmr::Error&) {
      // one rule's structural problem; the others are still validated
    }
  }
}
