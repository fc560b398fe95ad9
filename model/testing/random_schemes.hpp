// Random rule schemes for property tests, drawn deterministically from a seed with the
// portable `uniform` of random_maps.hpp.
//
//  * `random_scheme`: an arbitrary Jerboa-style scheme (rule_scheme.hpp) of dimension n: a random
//    orbit type <o>, an L of one hook node labelled <o> (sometimes a second L node joined to it by
//    an explicit arc), an R of preserved and added nodes whose labels are random positional
//    relabelings of <o> (each position a distinct dimension or `_`), and explicit arcs. The draw
//    is biased toward incident-arc-consistent schemes (every dimension a node lacks in its label is
//    completed by an explicit arc or loop, most of the time) so that the engine applies often,
//    but every condition of the scheme checker can fail. Structurally valid (validate_structure)
//    and usable by SchemeEngine (hooks without `_`, L connected to its hook).
//  * `mutate_scheme`: one random edit of a scheme (a label position changed or cleared, an
//    explicit arc added or removed, an added node dropped, a preserved node deleted), keeping the
//    structural validity above. Applied to the library operations, it gives "near miss" schemes.
#pragma once
#include "model/scheme/rule_scheme.hpp"
#include "model/testing/random_maps.hpp"

namespace gmr::testing {
using scheme::RuleScheme;

struct RandomSchemeOptions {
  int n = 2;
  size_t max_added = 3;  // added R nodes, uniform in [0, max]
  unsigned second_left_percent = 20;
  unsigned complete_percent = 90;  // chance that a missing dimension at an R node gets an arc
};
RuleScheme random_scheme(Rng& rng, const RandomSchemeOptions& opt = {});

// A scheme consistent by construction: <o> = <0..n>, L = the hook alone (its whole connected
// component), R = 1..max_nodes nodes, the hook preserved or deleted, each node labelled with the
// identity <0,..,n> or the reversal <n,..,0>. Its instance replaces a component by copies of it and
// of its dual (i -> n-i maps (0..n)_{+2} onto itself, so both copies are valid G-maps): the
// checker must accept it and every application must give a valid G-map.
RuleScheme random_copies_scheme(Rng& rng, int n, size_t max_nodes);

// The kind of edit made, for messages ("relabel R n1 position 0 -> _").
std::string mutate_scheme(Rng& rng, RuleScheme& s);

}  // namespace gmr::testing
