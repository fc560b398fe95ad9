// The "gmr.rule" file format, kind "scheme": Jerboa rule schemes. The
// concrete kind (DPO rules) is read by rule_json.hpp; both share the header keys "format",
// "version", "kind", "name", "description", "map", "n".
//
//   {
//     "format": "gmr.rule", "version": 1, "kind": "scheme",
//     "name": "quad_subdivision",            (optional)
//     "description": "...",                  (optional, free text)
//     "map": "gmap",                         schemes rewrite G-maps only
//     "n": 2,                                dimension: labels and arcs use 0..n
//     "orbit": "<0,1,2>",                    the parameter <o> of the scheme (no `_`)
//     "embeddings": [                        (optional) the embeddings the expressions write:
//       {"name": "position", "orbit": "<1,2>", "type": "point"} ],   value types point, vector,
//                                            scalar, colour (docs/embeddings.md)
//     "hooks": ["n0"],                       L nodes, one per connected component of L; the
//                                            first is the reference hook
//     "left":  { "nodes": [ {"name": "n0", "orbit": "<0,1,2>"} ],
//                "arcs":  [ {"nodes": ["n0", "n1"], "label": 0} ] },   explicit arcs, undirected;
//                                            the same node twice is a loop
//     "right": { "nodes": [ {"name": "n1", "orbit": "<_,_,2>",
//                            "expressions": [ {"embedding": "pos", "code": "..."} ]} ],
//                                            (imported from Jerboa: also "jerboa", the Java code,
//                                            and "unsupported" instead of "code" when it could
//                                            not be translated)
//                "arcs": [...] },
//     "precondition": "..."                  (optional, Jerboa code kept as text, never evaluated)
//   }
//
// Node "orbit" = the node's label, a positional relabeling of "orbit" (same arity; `_` deletes).
// The reader validates everything and throws the first problem as Error(Parse) (malformed JSON,
// line:column) or Error(Schema) located by JSON path (e.g. "$.right.nodes[2].orbit" for a wrong
// arity, "$.left.arcs[0].nodes[1]" for an unknown node, "$.hooks[0]" for a hook not in L). Whether
// the scheme is *consistent* (hooks per component, incident arcs, cycles, ...) is the scheme
// checker's business, not the reader's. Every expression is parsed and type-checked
// (docs/embeddings.md): a malformed or ill-typed expression, one for an undeclared embedding, two
// for one embedding on a node, or one on a deleted node is an error located
// "$.right.nodes[1].expressions[0].code (rule r, node n1), column 12". The writer writes
// atomically.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "model/scheme/rule_scheme.hpp"

namespace gmr::io {
using scheme::RuleScheme;

// The "kind" member of a gmr.rule document ("concrete", "scheme", ...), after checking the header;
// throws like the readers.
std::string rule_document_kind(const nlohmann::json& doc, const std::string& source = {});

RuleScheme scheme_from_json(const nlohmann::json& doc, const std::string& source = {});
RuleScheme parse_scheme(std::string_view text, const std::string& source = {});
RuleScheme read_scheme_file(const std::filesystem::path& path);

nlohmann::ordered_json scheme_to_json(const RuleScheme& s);
std::string scheme_to_json_text(const RuleScheme& s);
void write_scheme_file(const RuleScheme& s, const std::filesystem::path& path);

}  // namespace gmr::io
