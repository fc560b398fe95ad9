// Validation of conditions (checker/smt/condition_validation.hpp): the thesis conditions are sound
// and complete on the bounded families below, the three deliberately wrong variants are refuted
// with minimal counterexamples (no smaller family refutes them), both engines give the same counts,
// and condition plug-ins load, run in a child process and fail cleanly.
#include "checker/smt/condition_validation.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "checker/rule_check.hpp"
#include "checker/smt/condition_plugin.hpp"
#include "checker/smt/condition_registry.hpp"
#include "checker/smt/rule_space.hpp"
#include "checker/smt/scheme_conditions.hpp"
#include "checker/smt/validation_format.hpp"
#include "model/core/error.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::smt;

namespace {
ValidationReport run(const std::string& name, int n, MapKind kind, std::vector<int> labels,
                     int max_nodes, unsigned bound, Engine e = Engine::Smt) {
  const BuiltinCondition* c = find_builtin_condition(name);
  EXPECT_NE(c, nullptr) << name;
  const ValidationOptions o{.n = n,
                            .kind = kind,
                            .labels = std::move(labels),
                            .max_nodes = max_nodes,
                            .bound = bound,
                            .engine = e};
  return validate_condition(*c, o);
}

size_t nodes(const Rule& r) { return r.left().num_nodes() + r.added_nodes().size(); }

std::string plugin(const std::string& stem) {
  return gmr::testing::build_artifact("GMR_PLUGIN_DIR") + "/lib" + stem + ".so";
}
}  // namespace

TEST(ConditionValidation, ThesisConjunctionIsCheckRule) {
  for_each_rule(2, MapKind::GMap, 2, {0, 1, 2}, [](size_t k, const Rule& r) {
    if (k % 13) return true;
    EXPECT_EQ(thesis_conditions(r), checker::check_rule(r).ok()) << k;
    return !::testing::Test::HasFailure();
  });
}

TEST(ConditionValidation, ThesisSoundAndComplete1GMaps) {
  const ValidationReport s = run("thesis", 1, MapKind::GMap, {0, 1}, 2, 4, Engine::Smt);
  const ValidationReport m = run("thesis", 1, MapKind::GMap, {0, 1}, 2, 4, Engine::Enum);
  std::printf("%s%s", to_text(s).c_str(), to_text(m).c_str());
  EXPECT_TRUE(s.sound() && s.complete());
  EXPECT_EQ(s.rules, count_rules(1, 2) + count_rules(2, 2));
  EXPECT_EQ(s.checked, s.rules);
  EXPECT_EQ(s.holds, m.holds);
  EXPECT_EQ(s.vacuous, m.vacuous);
  EXPECT_EQ(s.unsound, m.unsound);
  EXPECT_EQ(s.incomplete, m.incomplete);
  EXPECT_GT(s.holds, 0u);
}

TEST(ConditionValidation, ThesisSoundAndCompleteOMapsAndCyclePair) {
  const ValidationReport o = run("thesis", 2, MapKind::OMap, {1, 2}, 2, 4);
  const ValidationReport g = run("thesis", 2, MapKind::GMap, {0, 2}, 2, 4);
  std::printf("%s%s", to_text(o).c_str(), to_text(g).c_str());
  EXPECT_TRUE(o.sound() && o.complete());
  EXPECT_TRUE(g.sound() && g.complete());
}

TEST(ConditionValidation, WrongIncidentArcsRefutedMinimally) {
  const ValidationReport r = run("wrong-incident-without-dangling", 1, MapKind::GMap, {0, 1}, 2, 4);
  ASSERT_FALSE(r.sound());
  const auto& w = *r.smallest_unsound;
  std::printf("%s", to_text(r).c_str());
  EXPECT_EQ(nodes(w.rule), 1u);
  EXPECT_EQ(w.counterexample->G.size(), 1u);
  EXPECT_TRUE(w.counterexample->gluing_fails);
}

TEST(ConditionValidation, WrongOrientationRefutedMinimally) {
  // Two nodes cannot break O without breaking I (a permutation of two darts is an involution).
  EXPECT_TRUE(run("wrong-orientation-dropped", 1, MapKind::GMap, {0}, 2, 4).sound());
  const ValidationReport r = run("wrong-orientation-dropped", 1, MapKind::GMap, {0}, 3, 4);
  std::printf("%s", to_text(r).c_str());
  ASSERT_FALSE(r.sound());
  const auto& w = *r.smallest_unsound;
  EXPECT_EQ(nodes(w.rule), 3u);
  EXPECT_EQ(w.counterexample->G.size(), 3u);
  EXPECT_EQ(w.counterexample->violations.front().constraint, Constraint::NonOrientation);
}

TEST(ConditionValidation, WrongCycleRefutedMinimally) {
  EXPECT_TRUE(run("wrong-cycle-without-completion", 2, MapKind::GMap, {0, 2}, 1, 4).complete());
  const ValidationReport r = run("wrong-cycle-without-completion", 2, MapKind::GMap, {0, 2}, 2, 4);
  std::printf("%s", to_text(r).c_str());
  EXPECT_FALSE(r.sound() && r.complete());
  ASSERT_TRUE(r.smallest_incomplete);
  EXPECT_EQ(nodes(r.smallest_incomplete->rule), 2u);
}

TEST(ConditionValidation, ShardsPartitionTheSweep) {
  const BuiltinCondition* c = find_builtin_condition("wrong-incident-without-dangling");
  ValidationOptions o{.n = 1, .labels = {0, 1}, .max_nodes = 2, .bound = 3};
  size_t rules = 0, unsound = 0, holds = 0;
  for (unsigned k = 0; k < 3; ++k) {
    o.shard = k;
    o.shards = 3;
    const auto r = validate_condition(*c, o);
    rules += r.rules;
    unsound += r.unsound;
    holds += r.holds;
  }
  const ValidationReport all = run(c->name, 1, MapKind::GMap, {0, 1}, 2, 3);
  EXPECT_EQ(rules, all.rules);
  EXPECT_EQ(unsound, all.unsound);
  EXPECT_EQ(holds, all.holds);
}

TEST(ConditionValidation, TimeLimitReportsCoverage) {
  const BuiltinCondition* c = find_builtin_condition("thesis");
  ValidationOptions o{.n = 1, .labels = {0}, .max_nodes = 3, .bound = 4, .time_limit = 0.3};
  const auto r = validate_condition(*c, o);
  EXPECT_TRUE(r.time_limit_hit);
  EXPECT_LT(r.checked, r.rules);
  EXPECT_LT(r.nodes_covered, 3);
}

TEST(ConditionPlugins, WorkedExampleSoundButIncomplete) {
  ConditionPlugin p(plugin("closed_components_condition"));
  EXPECT_EQ(p.name(), "closed-components");
  ValidationOptions o{.n = 1, .labels = {0, 1}, .max_nodes = 2, .bound = 4};
  auto eval = [&](const std::vector<Rule>& rs) { return p.evaluate(rs); };
  const auto one = validate_condition(p.name(), eval, o);
  std::printf("%s", to_text(one).c_str());
  EXPECT_TRUE(one.sound());
  EXPECT_FALSE(one.complete());
  EXPECT_EQ(one.smallest_incomplete->rule.left().num_nodes(), 1u);
  o.n = 2;
  o.kind = MapKind::OMap;
  o.labels = {1, 2};
  const auto omaps = validate_condition(p.name(), eval, o);
  std::printf("%s", to_text(omaps).c_str());
  EXPECT_TRUE(omaps.sound());
  EXPECT_FALSE(omaps.complete());
}

TEST(ConditionPlugins, BadPluginsFailNamingPluginAndRule) {
  std::vector<Rule> rules;
  for_each_rule(1, MapKind::GMap, 2, {0}, [&](size_t, const Rule& r) {
    rules.push_back(r);
    return rules.size() < 40;
  });
  auto message = [&](const std::string& stem) -> std::string {
    try {
      ConditionPlugin p(plugin(stem));
      p.evaluate(rules);
    } catch (const Error& e) {
      return e.location() + ": " + e.message();
    }
    return "";
  };
  const std::string thrown = message("throwing_condition");
  EXPECT_NE(thrown.find("throwing_condition"), std::string::npos) << thrown;
  EXPECT_NE(thrown.find("threw while evaluating rule rule"), std::string::npos) << thrown;
  EXPECT_NE(thrown.find("deleted nodes are not supported"), std::string::npos) << thrown;
  const std::string crashed = message("crashing_condition");
  // A signal, or (when a sanitizer keeps its own handler) an early exit of the child.
  EXPECT_TRUE(crashed.find("crashed (signal 11") != std::string::npos ||
              crashed.find("process exited") != std::string::npos)
      << crashed;
  EXPECT_NE(crashed.find("while evaluating rule rule"), std::string::npos) << crashed;
  const std::string missing = message("no_entry_condition");
  // A predicate that never returns: stopped by the per-evaluation time limit.
  std::string hung;
  try {
    ConditionPlugin p(plugin("hanging_condition"));
    p.evaluate(rules, 0.3);
  } catch (const Error& e) {
    hung = e.location() + ": " + e.message();
  }
  EXPECT_NE(hung.find("hanging_condition"), std::string::npos) << hung;
  EXPECT_NE(hung.find("did not return within the per-evaluation time limit of 0.3 s while "
                      "evaluating rule rule"),
            std::string::npos)
      << hung;
  EXPECT_NE(missing.find("no entry symbol gmr_condition_v1"), std::string::npos) << missing;
  const std::string absent = message("does_not_exist");
  EXPECT_NE(absent.find("cannot load"), std::string::npos) << absent;
}

TEST(ConditionValidation, RandomLargerRules) {
  const BuiltinCondition* c = find_builtin_condition("thesis");
  ValidationOptions o{
      .n = 1, .labels = {0, 1}, .max_nodes = 1, .bound = 6, .random = 300, .seed = 7};
  const auto r = validate_condition(*c, o);
  std::printf("%s", to_text(r).c_str());
  EXPECT_EQ(r.rules, count_rules(1, 2) + 300);
  EXPECT_TRUE(r.sound());
  EXPECT_TRUE(r.complete());
  EXPECT_GT(r.holds, 0u);
  // The enumerator agrees on every count.
  o.engine = Engine::Enum;
  const auto m = validate_condition(*c, o);
  EXPECT_EQ(m.holds, r.holds);
  EXPECT_EQ(m.vacuous, r.vacuous);
  EXPECT_EQ(m.unsound, r.unsound);
  EXPECT_EQ(m.incomplete, r.incomplete);
  o.engine = Engine::Smt;
  // Deterministic: the same seed gives the same counts.
  const auto again = validate_condition(*c, o);
  EXPECT_EQ(again.holds, r.holds);
  EXPECT_EQ(again.incomplete, r.incomplete);
}

// The worked example of a scheme condition (docs/examples/full_degree_scheme_condition.cpp): the
// plug-in's verdicts, evaluated in its child, equal the same predicate evaluated in process on the
// library schemes; the entry points a plug-in lacks are refused by name.
TEST(ConditionPlugins, SchemePluginWorkedExampleAgreesWithInProcessPredicate) {
  std::vector<scheme::RuleScheme> schemes;
  for (const auto& e :
       std::filesystem::directory_iterator(gmr::testing::source_path("tools/data/rules")))
    if (e.path().extension() == ".json") schemes.push_back(io::read_scheme_file(e.path()));
  ASSERT_EQ(schemes.size(), 16u);
  ConditionPlugin p(plugin("full_degree_scheme_condition"));
  EXPECT_TRUE(p.judges_schemes());
  EXPECT_FALSE(p.judges_rules());
  EXPECT_EQ(p.scheme_name(), "full-degree");
  const std::vector<bool> got = p.evaluate_schemes(schemes);
  size_t holds = 0;
  for (size_t k = 0; k < schemes.size(); ++k) {
    const auto& s = schemes[k];
    bool expected = true;
    for (const auto* g : {&s.left, &s.right})
      for (uint32_t v = 0; v < g->size(); ++v)
        for (int d = 0; d <= s.dimension; ++d) expected = expected && g->count_arcs(v, d) == 1;
    EXPECT_EQ(got[k], expected) << s.name;
    holds += expected;
  }
  EXPECT_GT(holds, 0u);
  EXPECT_LT(holds, schemes.size());
  const SchemeValidationReport r = validate_scheme_condition("full-degree", got, schemes, 3);
  EXPECT_EQ(r.holds, holds);
  EXPECT_TRUE(r.sound()) << to_text(r);
  EXPECT_THROW(p.evaluate({}), Error);
  ConditionPlugin rules_only(plugin("closed_components_condition"));
  EXPECT_FALSE(rules_only.judges_schemes());
  EXPECT_THROW(rules_only.evaluate_schemes(schemes), Error);
}
