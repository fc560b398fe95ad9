// Text and JSON of the checkers' reports (diagnostic.hpp), format "gmr.check", version 1
// (docs/check-format.md): the one writer of a CheckReport, whether it comes from the concrete-rule
// checker (rule_check.hpp) or the scheme checker (scheme_checker.hpp); the text and the JSON follow
// the report's subject. Also the text of a semantic verdict's witness (semantic.hpp).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "checker/diagnostic.hpp"
#include "checker/semantic.hpp"

namespace gmr::checker {

std::string to_text(const Diagnostic& d);
std::string to_text(const CheckReport& r);
nlohmann::ordered_json to_json(const Diagnostic& d);
nlohmann::ordered_json to_json(const CheckReport& r);

// The header every gmr.check document starts with:
// {"format": "gmr.check", "version": 1, "subject": subject, "ok": ok}; subject is "rule" (a
// concrete rule), "scheme" (a rule scheme) or "modeler" (a batch of .jme rule schemes).
nlohmann::ordered_json check_document(const char* subject, bool ok);

// The witness of a semantic verdict (semantic.hpp): "map #k (n darts; alpha0=[...] ...), match
// a->0 ...; H breaks: <the first three violations>".
std::string to_text(const SemanticWitness& w, const Rule& r, const MapFamily& f);

}  // namespace gmr::checker
