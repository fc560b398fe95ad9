// Running a property (issue 5): replay the corpus first, then RapidCheck's random search.
//
// The corpus (proptests/corpus/<property>.txt, one case per line: "<family> <n> <size> <seed>")
// holds counterexamples found by fuzzing campaigns (tools/fuzz); every later run replays them
// before searching. When the environment variable GMR_CORPUS_OUT names a file, a failing
// property appends its shrunk case there ("<property> <family> <n> <size> <seed>"), which is how
// tools/fuzz collects findings from its shards.
// RapidCheck's own parameters come from RC_PARAMS (seed, max_success, max_size, reproduce).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "proptests/generators.hpp"

namespace gmr::prop {

using MapProperty = std::function<void(const MapCase&)>;

// Corpus cases recorded for `property`.
std::vector<MapCase> corpus_cases(const std::string& property);
// Replays the corpus, then checks the property on generated cases. Returns true when it holds.
bool check_map_property(const std::string& property, const rc::Gen<MapCase>& gen, const MapProperty& body);

}  // namespace gmr::prop
