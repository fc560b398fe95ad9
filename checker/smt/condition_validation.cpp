#include "checker/smt/condition_validation.hpp"

#include <chrono>

#include "checker/smt/rule_space.hpp"
#include "model/core/error.hpp"

namespace gmr::smt {

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
size_t nodes_of(const Rule& r) { return r.left().num_nodes() + r.added_nodes().size(); }
}  // namespace

ValidationReport validate_condition(const std::string& name, const ConditionEvaluator& evaluate,
                                    const ValidationOptions& opt) {
  if (opt.shards == 0 || opt.shard >= opt.shards)
    throw Error(ErrorCode::Usage,
                "shard " + std::to_string(opt.shard) + " of " + std::to_string(opt.shards),
                "--shard");
  const auto t0 = std::chrono::steady_clock::now();
  ValidationReport rep;
  rep.condition = name;
  rep.options = opt;
  std::vector<Rule> rules;
  std::vector<size_t> index;
  for_each_rule(opt.n, opt.kind, opt.max_nodes, opt.labels, [&](size_t k, const Rule& r) {
    if (k % opt.shards == opt.shard) {
      rules.push_back(r);
      index.push_back(k);
    }
    return true;
  });
  size_t next = 0;  // the family's size: random rules are indexed after it
  for (int m = 1; m <= opt.max_nodes; ++m) next += count_rules(m, opt.labels.size());
  std::mt19937_64 rng(opt.seed);
  for (size_t k = 0; k < opt.random; ++k) {
    const int nodes = opt.max_nodes + 1 + static_cast<int>(rng() % 2);
    Rule r = random_rule(rng, opt.n, opt.kind, nodes, opt.labels, "random" + std::to_string(k));
    if ((next + k) % opt.shards == opt.shard) {
      rules.push_back(std::move(r));
      index.push_back(next + k);
    }
  }
  rep.rules = rules.size();
  const auto tc = std::chrono::steady_clock::now();
  const std::vector<bool> holds = evaluate(rules);
  rep.condition_seconds = since(tc);
  EncodingOptions eo;
  eo.semantics = Semantics::Consistency;
  std::optional<SmtSession> session;
  std::optional<graph::MapFamily> family;
  if (opt.engine == Engine::Smt)
    session.emplace(MapSpec{opt.n, opt.kind}, opt.bound,
                    static_cast<unsigned>(opt.max_nodes + (opt.random ? 2 : 0)), eo);
  else
    family.emplace(graph::map_family(opt.n, opt.kind, opt.bound));
  auto last_progress = std::chrono::steady_clock::now();
  rep.nodes_covered = opt.max_nodes;
  for (size_t k = 0; k < rules.size(); ++k) {
    if (opt.time_limit > 0 && since(t0) > opt.time_limit) {
      rep.time_limit_hit = true;
      rep.nodes_covered = std::min(opt.max_nodes, static_cast<int>(nodes_of(rules[k])) - 1);
      break;
    }
    const Rule& r = rules[k];
    const VerifyResult v =
        session ? session->verify(r) : verify_enum(r, *family, Semantics::Consistency);
    ++rep.checked;
    (holds[k] ? rep.holds : rep.fails)++;
    if (!v.applicable) {
      ++rep.vacuous;
    } else if (holds[k] && !v.preserves) {
      ++rep.unsound;
      const auto& cur = rep.smallest_unsound;
      if (!cur || nodes_of(r) < nodes_of(cur->rule) ||
          (nodes_of(r) == nodes_of(cur->rule) &&
           v.counterexample->G.size() < cur->counterexample->G.size()))
        rep.smallest_unsound = ValidationWitness{r, index[k], v.counterexample};
    } else if (!holds[k] && v.preserves) {
      ++rep.incomplete;
      if (!rep.smallest_incomplete)
        rep.smallest_incomplete = ValidationWitness{r, index[k], std::nullopt};
    }
    if (opt.progress &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_progress).count() >
            0.5) {
      opt.progress(k + 1, rules.size());
      last_progress = std::chrono::steady_clock::now();
    }
  }
  if (opt.progress) opt.progress(rep.checked, rules.size());
  rep.seconds = since(t0);
  return rep;
}

ValidationReport validate_condition(const BuiltinCondition& c, const ValidationOptions& opt) {
  return validate_condition(
      c.name,
      [&](const std::vector<Rule>& rules) {
        std::vector<bool> out;
        out.reserve(rules.size());
        for (const Rule& r : rules) out.push_back(c.holds(r));
        return out;
      },
      opt);
}

}  // namespace gmr::smt
