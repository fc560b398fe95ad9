// Condition plug-ins (condition_api.hpp) loaded with dlopen, and their guarded evaluation
// (docs/verify.md, "Condition plug-ins").
//
// Loading: dlopen(path, RTLD_NOW | RTLD_LOCAL), then dlsym("gmr_condition_v1") and
// dlsym("gmr_scheme_condition_v1") (either or both); a library that does not load, lacks both or
// returns a null description is a located Error(Usage) naming the plug-in. The library is loaded in
// the gmr process (its static initialisers run there). Evaluation: `evaluate` runs the predicate on
// every rule in ONE forked child process, which sends one byte per rule back through a pipe. A
// predicate that throws (the child reports the message) or crashes (the child dies on a signal, or
// exits early) stops the evaluation with an Error(Usage) naming the plug-in, the rule it was
// evaluating and the signal or message; the gmr process itself survives and exits 2. A predicate
// that does not return within the per-evaluation time limit (wall clock, a real-time interval timer
// re-armed before each rule in the child; the child dies on SIGALRM) is the same kind of error,
// naming the limit.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "checker/smt/condition_api.hpp"
#include "model/rewrite/rule.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::smt {

inline constexpr const char* kConditionEntrySymbol = "gmr_condition_v1";
inline constexpr const char* kSchemeConditionEntrySymbol = "gmr_scheme_condition_v1";

class ConditionPlugin {
 public:
  explicit ConditionPlugin(const std::string& path);
  ~ConditionPlugin();
  ConditionPlugin(const ConditionPlugin&) = delete;
  ConditionPlugin& operator=(const ConditionPlugin&) = delete;

  const std::string& path() const { return path_; }
  std::string name() const;  // of the rule condition (of the scheme condition if there is none)
  std::string description() const;
  std::string scheme_name() const;
  bool judges_rules() const { return condition_ != nullptr; }
  bool judges_schemes() const { return scheme_condition_ != nullptr; }
  // holds(rule) for every rule, evaluated in a child process (see above); each evaluation may
  // take at most `eval_timeout` seconds (0: no limit).
  std::vector<bool> evaluate(const std::vector<rewrite::Rule>& rules,
                             double eval_timeout = kDefaultEvalTimeout) const;
  static constexpr double kDefaultEvalTimeout = 10;
  // holds(scheme) for every scheme, guarded the same way (the optional entry point).
  std::vector<bool> evaluate_schemes(const std::vector<scheme::RuleScheme>& schemes,
                                     double eval_timeout = kDefaultEvalTimeout) const;

 private:
  std::string path_;
  void* handle_ = nullptr;
  const gmr_condition* condition_ = nullptr;
  const gmr_scheme_condition* scheme_condition_ = nullptr;
  std::vector<bool> run_guarded(size_t count, const std::function<bool(size_t)>& holds,
                                const std::function<std::string(size_t)>& describe,
                                double eval_timeout) const;
};

}  // namespace gmr::smt
