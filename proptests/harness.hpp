// Running a property: replay the corpus first, then RapidCheck's random search.
//
// The corpus (proptests/corpus/<property>.txt, one case per line: "<family> <n> <size> <seed>")
// holds counterexamples found by fuzzing campaigns (tools/fuzz); every later run replays them
// before searching. When the environment variable GMR_CORPUS_OUT names a file, a failing
// property appends its shrunk case there ("<property> <family> <n> <size> <seed>"), which is how
// tools/fuzz collects findings from its shards.
// RapidCheck's own parameters come from RC_PARAMS (seed, max_success, max_size, reproduce); a
// failing run prints the RapidCheck seed and `reproduce` string, and the shrunk case through its
// showValue (JSON and DOT diagram).
//
// A case type `Case` (MapCase, RuleCase, SchemeCase) provides `static std::optional<Case>
// parse(const std::string& line)`, `std::string corpus_line() const` and `std::string str() const`.
#pragma once
#include <rapidcheck.h>

#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace gmr::prop {

// Lines of proptests/corpus/<property>.txt (comments and blank lines skipped).
std::vector<std::string> corpus_lines(const std::string& property);
// Appends "<property> <line>" to $GMR_CORPUS_OUT, if set.
void record_finding(const std::string& property, const std::string& line);

template <class Case>
bool check_property(const std::string& property, const rc::Gen<Case>& gen,
                    const std::function<void(const Case&)>& body) {
  for (const std::string& line : corpus_lines(property)) {
    const auto c = Case::parse(line);
    if (!c) {
      std::cerr << "corpus " << property << ": ignoring malformed line: " << line << "\n";
      continue;
    }
    // Through rc::gen::just so that RapidCheck shows the case (showValue: JSON and diagram).
    if (!rc::check(property + " (corpus " + c->str() + ")", [&] { body(*rc::gen::just(*c)); }))
      return false;
  }
  Case last_failure{};
  bool failed_once = false;
  const bool ok = rc::check(property, [&] {
    const Case c = *gen;
    try {
      body(c);
    } catch (...) {
      last_failure = c;  // the last failing evaluation is the shrunk counterexample
      failed_once = true;
      throw;
    }
  });
  if (!ok && failed_once) {
    std::cerr << "shrunk counterexample: " << last_failure.str() << "\n";
    record_finding(property, last_failure.corpus_line());
  }
  return ok;
}

}  // namespace gmr::prop
