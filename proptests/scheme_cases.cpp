#include "proptests/scheme_cases.hpp"

#include <stdexcept>

#include "model/draw/rule_dot.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/random_schemes.hpp"
#include "proptests/case_line.hpp"
#include "proptests/library.hpp"

namespace gmr::prop {
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::draw;
using namespace gmr::testing;

const char* to_string(SchemeFamily f) {
  switch (f) {
    case SchemeFamily::Random:
      return "random";
    case SchemeFamily::LibraryMutant:
      return "library-mutant";
    case SchemeFamily::Library:
      return "library";
    case SchemeFamily::Copies:
      return "copies";
  }
  return "?";
}

RuleScheme SchemeCase::build() const {
  Rng rng(seed);
  if (family == SchemeFamily::Copies) return random_copies_scheme(rng, n, size + 1);
  if (family == SchemeFamily::Random) {
    RandomSchemeOptions o;
    o.n = n;
    o.max_added = size;
    return random_scheme(rng, o);
  }
  const std::vector<size_t> lib = library_of_dim(n, false);
  if (lib.empty()) throw std::logic_error("no library scheme of dimension " + std::to_string(n));
  RuleScheme s = scheme_library()[lib[seed % lib.size()]].scheme;
  if (family == SchemeFamily::LibraryMutant)
    for (size_t k = 0; k < size; ++k) mutate_scheme(rng, s);
  return s;
}

std::string SchemeCase::str() const { return "SchemeCase{" + corpus_line() + "}"; }

std::string SchemeCase::corpus_line() const {
  return CaseLine{to_string(family), n, size, seed}.str();
}

std::optional<SchemeCase> SchemeCase::parse(const std::string& line) {
  const auto l = CaseLine::parse(line);
  if (!l || l->n < 1 || l->n > 3) return std::nullopt;
  for (SchemeFamily f : {SchemeFamily::Random, SchemeFamily::LibraryMutant, SchemeFamily::Library,
                         SchemeFamily::Copies})
    if (l->family == to_string(f)) {
      if ((f == SchemeFamily::LibraryMutant || f == SchemeFamily::Library) && l->n < 2)
        return std::nullopt;
      return SchemeCase{f, l->n, l->size, l->seed};
    }
  return std::nullopt;
}

rc::Gen<SchemeCase> gen_scheme_case_of_dim(int n) {
  std::vector<SchemeFamily> fams{SchemeFamily::Random, SchemeFamily::Copies};
  if (n >= 2) fams.insert(fams.end(), {SchemeFamily::LibraryMutant, SchemeFamily::Library});
  return rc::gen::apply(
      [n](SchemeFamily f, size_t size, uint64_t seed) {
        return SchemeCase{f, n, size, seed};
      },
      rc::gen::elementOf(fams), rc::gen::inRange<size_t>(1, 4),
      rc::gen::inRange<uint64_t>(0, 1u << 20));
}

rc::Gen<SchemeCase> gen_copies_scheme_case() {
  return rc::gen::apply(
      [](int n, size_t size, uint64_t seed) {
        return SchemeCase{SchemeFamily::Copies, n, size, seed};
      },
      rc::gen::inRange(1, 4), rc::gen::inRange<size_t>(1, 4),
      rc::gen::inRange<uint64_t>(0, 1u << 20));
}

std::string describe_scheme(const RuleScheme& s) {
  return "--- scheme (gmr.rule) ---\n" + scheme_to_json_text(s) + "\n--- diagram (DOT) ---\n" +
         to_dot(s);
}

}  // namespace gmr::prop
