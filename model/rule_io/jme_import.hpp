// Import of Jerboa modeler files (.jme, XML) into rule schemes.
//
// The file's <modeler dimension="n"> gives the dimension; each <rule name=...> becomes a
// RuleScheme:
//  * <left>/<right> <nodes>: <node name=.. orbit="0,-1,2" kind="HOOK|SIMPLE"> — the orbit attribute
//    is the node label, -1 standing for `_`, "" for <>; <expr ebd="pos">code</expr> children of
//    right nodes are translated into gmr's expression language (jme_expression.hpp) and checked,
//    the Java code kept in EmbeddingExpression::jerboa; those that do not translate carry the
//    reason in `unsupported`;
//  * the modeler's <embedding name= type= orbit=> become every rule's embedding declarations
//    (Jerboa's Vec3 -> point, Color -> colour);
//  * <arcs>: <arc dim=.. a=.. b=..> explicit arcs, <arcloop dim=.. node=..> explicit loops;
//  * hooks: L nodes of kind HOOK, ordered by <paramtopo name=.. order=..> when present, else in
//    document order; the rule's orbit type <o> is the first hook's label. A rule without hook takes
//    <o> = the label of its first node when that label has no `_`, else <_,...> of that arity is
//    impossible and <o> is left empty (the checker reports it);
//  * <comment> -> description, <precondition> -> precondition (kept, never evaluated); the other
//    code blocks (header, pre/mid/postprocess, paramsebd) are ignored.
// Layout attributes (x, y, angle, color, shape, ...) are ignored. The importer is tolerant on
// scheme consistency (wrong arity, `_` in hooks, ...: the checker reports them) but strict on the
// file: malformed XML, a missing attribute, a non-integer dimension, an arc naming an unknown
// node or two rules of one name is an Error (Parse, Schema) located "<file>:<line>".
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "model/scheme/rule_scheme.hpp"

namespace gmr::io {
using scheme::RuleScheme;

struct JmeEmbedding {
  std::string name, type;
  OrbitType orbit;
};

struct JmeModeler {
  std::string name;
  int dimension = 0;
  std::vector<JmeEmbedding> embeddings;
  std::vector<RuleScheme> rules;
  std::vector<size_t> rule_lines;  // line of each <rule> in the file
};

JmeModeler parse_jme(std::string_view text, const std::string& source = {});
JmeModeler read_jme_file(const std::filesystem::path& path);

// "-1,2,3" -> <_,2,3>; "" -> <>. Throws Error(Parse) for anything else.
OrbitType parse_jme_orbit(std::string_view text);

}  // namespace gmr::io
