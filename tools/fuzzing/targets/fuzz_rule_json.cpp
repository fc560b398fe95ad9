// gmr.rule JSON, concrete rules and rule schemes: read, then the scheme's structural validation
// (what `gmr apply` checks before running the engine) and a write/read round trip.
#include "model/map_io/json_reader.hpp"
#include "model/rule_io/rule_json.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  const nlohmann::json doc = io::parse_json(text, "fuzz.json");
  if (io::rule_document_kind(doc, "fuzz.json") == "scheme") {
    const scheme::RuleScheme s = io::scheme_from_json(doc, "fuzz.json");
    s.validate_structure();
    (void)io::parse_scheme(io::scheme_to_json_text(s), "written.json");
  } else {
    const rewrite::Rule r = io::rule_from_json(doc, "fuzz.json");
    (void)io::rule_from_json(io::rule_to_json(r), "written.json");
  }
}
