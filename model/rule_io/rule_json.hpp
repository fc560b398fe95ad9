// The "gmr.rule" file format for concrete DPO rules.
//
//   {
//     "format": "gmr.rule", "version": 1, "kind": "concrete",
//     "name": "sew-2",                      (optional)
//     "description": "...",                 (optional, free text)
//     "map": "gmap" | "omap",               the model: labels 0..n (G-maps) or 1..n (O-maps)
//     "n": 2,
//     "left":  { "nodes": ["a", "b"],
//                "arcs":  [ {"from": "a", "to": "b", "label": 0}, ... ],      directed arcs
//                "links": [ {"nodes": ["a", "b"], "label": 0}, ... ] },      optional shorthand:
//                                         a non-oriented link = two opposite arcs (a loop = one
//                                         arc)
//     "right": { ... }
//   }
//
// Preserved nodes are the names present on both sides; preserved arcs are deduced (Assumption 4).
// The reader validates everything and throws the FIRST problem as Error(Parse) (malformed JSON,
// located line:column) or Error(Schema) located by JSON path, e.g. "$.left.arcs[3].label" for a
// label outside the dimension set, "$.right.arcs[0].to" for an unknown node name,
// "$.left.nodes[2]" for a duplicate name. The writer emits arcs only (no "links") and writes
// atomically (write_file_atomic: temp file in the same directory + rename).
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "model/rewrite/rule.hpp"

namespace gmr::io {
using rewrite::Rule;

Rule rule_from_json(const nlohmann::json& doc, const std::string& source = {});
Rule parse_rule(std::string_view text, const std::string& source = {});
Rule read_rule_file(const std::filesystem::path& path);

nlohmann::ordered_json rule_to_json(const Rule& r);
void write_rule_file(const Rule& r, const std::filesystem::path& path);

}  // namespace gmr::io
