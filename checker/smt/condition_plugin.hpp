// Condition plug-ins (condition_api.hpp) loaded with dlopen, and their guarded evaluation
// (docs/verify.md, "Condition plug-ins").
//
// Loading: dlopen(path, RTLD_NOW | RTLD_LOCAL), then dlsym("gmr_condition_v1"); a library that
// does not load, lacks the symbol or returns a null description is a located Error(Usage) naming
// the plug-in. The library is loaded in the gmr process (its static initialisers run there).
// Evaluation: `evaluate` runs the predicate on every rule in ONE forked child process, which sends
// one byte per rule back through a pipe. A predicate that throws (the child reports the message)
// or crashes (the child dies on a signal, or exits early) stops the evaluation with an
// Error(Usage) naming the plug-in, the rule it was evaluating and the signal or message; the gmr
// process itself survives and exits 2. A predicate that does not return within the per-evaluation
// time limit (wall clock, a real-time interval timer re-armed before each rule in the child; the
// child dies on SIGALRM) is the same kind of error, naming the limit.
#pragma once
#include <string>
#include <vector>

#include "checker/smt/condition_api.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::smt {

inline constexpr const char* kConditionEntrySymbol = "gmr_condition_v1";

class ConditionPlugin {
 public:
  explicit ConditionPlugin(const std::string& path);
  ~ConditionPlugin();
  ConditionPlugin(const ConditionPlugin&) = delete;
  ConditionPlugin& operator=(const ConditionPlugin&) = delete;

  const std::string& path() const { return path_; }
  std::string name() const;
  std::string description() const;
  // holds(rule) for every rule, evaluated in a child process (see above); each evaluation may
  // take at most `eval_timeout` seconds (0: no limit).
  std::vector<bool> evaluate(const std::vector<rewrite::Rule>& rules, double eval_timeout = kDefaultEvalTimeout) const;
  static constexpr double kDefaultEvalTimeout = 10;

 private:
  std::string path_;
  void* handle_ = nullptr;
  const gmr_condition* condition_ = nullptr;
};

}  // namespace gmr::smt
