// The native G-map format "gmr.gmap", version 1.
//
//   {
//     "format": "gmr.gmap",
//     "version": 1,
//     "kind": "gmap" | "omap",
//     "dimension": n,                    // 0..30 for a G-map, 1..30 for an O-map
//     "darts": N,                        // darts are 0..N-1
//     "alpha": {                         // one member per dimension of the map: "0".."n" for a
//       "0": [t_0, ..., t_{N-1}],        // G-map, "1".."n" for an O-map ("1" holds beta_1);
//       ...                              // t_d is the target of the link leaving dart d, a free
//     },                                 // dart is a loop (t_d == d)
//     "embeddings": [                    // optional
//       {"name": "position", "orbit": "<1,2>",
//        "values": [{"dart": d, "value": <any JSON>}, ...]}   // one entry per orbit that has a
//        value
//     ]
//   }
//
// Reading validates everything and throws the first problem as Error(Parse) (malformed JSON,
// located "<file>:<line>:<column>") or Error(Schema) located by JSON path ("<file>:$.alpha.1[7]"):
// wrong format tag or version, unknown or missing members, wrong types, a dimension key the map
// does not have, an array whose length is not N, a dart index outside 0..N-1 (in "alpha" or in
// "values"), a malformed or foreign orbit type, a duplicate embedding name, two values for one
// orbit. Values are typed on reading (EmbeddedMap, embedded_map.hpp): numbers and triples as
// numbers, anything else kept as JSON. Whether the links form a valid G-map is *not* checked: the
// map is returned as written and check_validity (validity.hpp) reports its violations. Values of an
// embedding are stored once per orbit (Embedding::set on the orbit of the given dart), which is
// also why a second value for the same orbit is rejected; orbits without a value are allowed
// (Embedding::check reports them).
//
// Writing numbers the live darts densely in increasing index order (a map with deleted darts is
// compacted) and writes one value per orbit that has one, at the orbit's smallest dart. Files are
// written atomically.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "model/core/embedded_map.hpp"
#include "model/map_io/json_reader.hpp"

namespace gmr::io {

inline constexpr const char* kGMapFormat = "gmr.gmap";
inline constexpr int kGMapVersion = 1;

// Reads a gmr.gmap object at `at` (for documents that embed a map, e.g. counterexamples).
EmbeddedMap map_from_json(const JsonAt& at);
EmbeddedMap read_map_json(std::string_view text, const std::string& source = {});
EmbeddedMap read_map_json_file(const std::filesystem::path& path);

nlohmann::ordered_json map_to_json(const Map& g, const std::vector<EmbeddingField>& fields = {});
std::string write_map_json(const Map& g, const std::vector<EmbeddingField>& fields = {});
inline std::string write_map_json(const EmbeddedMap& f) { return write_map_json(f.map, f.fields); }
void write_map_json_file(const std::filesystem::path& path, const EmbeddedMap& f);

}  // namespace gmr::io
