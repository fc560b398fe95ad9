// RapidCheck generators of rule schemes, as deterministic `SchemeCase`s (family,
// dimension, size, seed; corpus line "<family> <n> <size> <seed>"):
//   random          random_scheme (model/random_schemes.hpp): arbitrary schemes, biased toward
//                   incident-arc consistency, up to `size` added nodes (n = 1..3);
//   library-mutant  a library scheme of dimension n (proptests/library.hpp) after `size` random
//                   edits (mutate_scheme) — near misses of real operations (n = 2, 3);
//   library         a library scheme unchanged (n = 2, 3);
//   copies          random_copies_scheme: consistent by construction (a component replaced by
//                   copies of it and of its dual), n = 1..3.
// Valid schemes: the copies family by construction; otherwise the ones the scheme checker accepts.
#pragma once
#include <rapidcheck.h>

#include <optional>
#include <ostream>
#include <string>

#include "model/scheme/rule_scheme.hpp"

namespace gmr::prop {
using scheme::RuleScheme;

enum class SchemeFamily { Random, LibraryMutant, Library, Copies };
const char* to_string(SchemeFamily f);

struct SchemeCase {
  SchemeFamily family = SchemeFamily::Random;
  int n = 2;
  size_t size = 1;
  uint64_t seed = 0;
  RuleScheme build() const;
  std::string str() const;
  std::string corpus_line() const;
  static std::optional<SchemeCase> parse(const std::string& line);
};

rc::Gen<SchemeCase> gen_scheme_case_of_dim(int n);
rc::Gen<SchemeCase> gen_copies_scheme_case();

std::string describe_scheme(const RuleScheme& s);
inline void showValue(const SchemeCase& c, std::ostream& os) {
  os << c.str() << "\n" << describe_scheme(c.build());
}

}  // namespace gmr::prop
