// The cycle condition C_r tabulated on every component pattern of a few nodes (docs/verify.md,
// "The cycle condition by components"; proofs/README.md, "C_r by components").
//
// A component pattern is a rule of k nodes, named in the family's status order (preserved <
// deleted < added along the nodes), with arcs on the cycle labels only (a partial injection per
// label and side), connected under them (either side, either direction), and satisfying, on each
// cycle label, the parts of Theorems 1-2 that the condition contains (w-I_r always; the dangling
// part of I_r and O_r when the condition has them). Every component of a rule of the family that
// satisfies the condition's Theorems 1-2 is, named in status order, one of these patterns: those
// conditions are per node and per arc, and a component holds every cycle-label arc of its nodes.
// The table gives each pattern the concrete checker's verdict (cycle_condition on the pattern, in
// the condition's reading): by the decomposition of cycle_components.hpp, the verdict of C_r on
// every placement of the pattern in a rule (symbolic_cycle.hpp, table_lemmas).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "checker/smt/condition_registry.hpp"
#include "checker/smt/symbolic_validation.hpp"
#include "model/core/map_spec.hpp"

namespace gmr::smt {

struct ComponentPattern {
  std::vector<int> status;     // per node: 0 preserved, 1 deleted, 2 added (nondecreasing)
  std::vector<uint64_t> arcs;  // [side * labels + l]: bit x * k + y is the arc x -> y (side 0 = L)
  bool holds = false;          // C_r on the pattern (the checker)
  size_t nodes() const { return status.size(); }
  bool arc(bool right, size_t l, size_t labels, size_t x, size_t y) const {
    return (arcs[(right ? labels : 0) + l] >> (x * nodes() + y)) & 1u;
  }
};

struct CycleTable {
  std::vector<int> labels;  // the cycle labels that carry arcs in the family (arcs[.] order)
  int max_nodes = 0;        // every pattern of at most this many nodes is in the table
  std::vector<ComponentPattern> patterns;
};

// A cube over the variables of a k-node pattern (pattern_bits): variable 2x is "node x is in L",
// 2x + 1 "node x is in R", 2k + ((side * labels + l) * k + x) * k + y "the side has the arc x -> y
// of the l-th label". `care` marks the variables the cube fixes, `value` their values.
using PatternBits = std::array<uint64_t, 2>;
struct PatternCube {
  size_t nodes = 0;
  bool holds = false;  // the verdict of every pattern of the table in the cube
  PatternBits care{}, value{};
};
PatternBits pattern_bits(const ComponentPattern& p, size_t labels);
// The number of variables of a k-node pattern (at most 128 for the cubes).
size_t pattern_variables(size_t k, size_t labels);

// Cubes that together contain every pattern of the table with the verdict `verdict` and no
// pattern with the other: each such pattern with as many variables dropped as keep every pattern
// of the other verdict and of its size out (greedy, in variable order from the last). A pattern of
// the family inside a cube therefore has that verdict, or is not a component satisfying Theorems
// 1-2 (then C_r does not read it).
std::vector<PatternCube> verdict_cubes(const CycleTable& table, bool verdict);
inline std::vector<PatternCube> failing_cubes(const CycleTable& table) {
  return verdict_cubes(table, false);
}

// The pattern of a set of nodes of a rule (a component): the nodes in the family's status order
// (stable on the given order), their statuses and their arcs on `labels` (holds left false).
ComponentPattern component_pattern(const rewrite::Rule& r, std::vector<std::string> nodes,
                                   const std::vector<int>& labels);

// Every component pattern of 1..max_nodes nodes (max_nodes <= 4: 107,480 connected 4-node
// patterns on the labels 0, 2 of 2-G-maps) with its verdict in `reading`. `rule_labels` are the
// labels that carry arcs in the family (arcs on the other cycle labels are absent).
CycleTable cycle_table(const MapSpec& spec, const std::vector<int>& rule_labels, int max_nodes,
                       const ThesisParts& parts, CycleReading reading);

}  // namespace gmr::smt
