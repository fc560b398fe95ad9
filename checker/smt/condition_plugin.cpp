#include "checker/smt/condition_plugin.hpp"

#include <dlfcn.h>
#include <signal.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>

#include "checker/smt/rule_space.hpp"
#include "checker/smt/rule_view.hpp"
#include "model/core/error.hpp"

namespace gmr::smt {

ConditionPlugin::ConditionPlugin(const std::string& path) : path_(path) {
  handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) {
    const char* e = dlerror();
    throw Error(ErrorCode::Usage,
                std::string("cannot load the condition plug-in: ") + (e ? e : "unknown error"),
                "plugin " + path);
  }
  dlerror();
  void* sym = dlsym(handle_, kConditionEntrySymbol);
  void* scheme_sym = dlsym(handle_, kSchemeConditionEntrySymbol);
  if (!sym && !scheme_sym) {
    dlclose(handle_);
    throw Error(ErrorCode::Usage,
                std::string("the condition plug-in has no entry symbol ") + kConditionEntrySymbol +
                    " or " + kSchemeConditionEntrySymbol +
                    " (extern \"C\"; see checker/smt/condition_api.hpp)",
                "plugin " + path);
  }
  if (sym) {
    using Entry = const gmr_condition* (*)();
    condition_ = reinterpret_cast<Entry>(sym)();
  }
  if (scheme_sym) {
    using Entry = const gmr_scheme_condition* (*)();
    scheme_condition_ = reinterpret_cast<Entry>(scheme_sym)();
  }
  if ((sym && (!condition_ || !condition_->holds)) ||
      (scheme_sym && (!scheme_condition_ || !scheme_condition_->holds))) {
    dlclose(handle_);
    throw Error(ErrorCode::Usage, "an entry symbol returned no condition (null predicate)",
                "plugin " + path);
  }
}

ConditionPlugin::~ConditionPlugin() {
  if (handle_) dlclose(handle_);
}

std::string ConditionPlugin::name() const {
  const char* n = condition_ ? condition_->name : scheme_condition_->name;
  return n ? n : path_;
}
std::string ConditionPlugin::description() const {
  const char* d = condition_ ? condition_->description : scheme_condition_->description;
  return d ? d : "";
}
std::string ConditionPlugin::scheme_name() const {
  return scheme_condition_ && scheme_condition_->name ? scheme_condition_->name : path_;
}

namespace {
void write_all(int fd, const char* p, size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) _exit(4);
    p += w;
    n -= static_cast<size_t>(w);
  }
}
}  // namespace

std::vector<bool> ConditionPlugin::evaluate(const std::vector<rewrite::Rule>& rules,
                                            double eval_timeout) const {
  if (!condition_)
    throw Error(
        ErrorCode::Usage,
        std::string("the plug-in judges rule schemes only (no ") + kConditionEntrySymbol + ")",
        "plugin " + path_);
  // The views are built before the fork: the child only runs the predicate and writes.
  std::vector<condition::RuleView> views;
  views.reserve(rules.size());
  for (const auto& r : rules) views.push_back(to_view(r));
  return run_guarded(
      views.size(), [&](size_t k) { return condition_->holds(views[k]); },
      [&](size_t k) { return "rule " + rules[k].name() + " (" + rule_text(rules[k]) + ")"; },
      eval_timeout);
}

std::vector<bool> ConditionPlugin::evaluate_schemes(const std::vector<scheme::RuleScheme>& schemes,
                                                    double eval_timeout) const {
  if (!scheme_condition_)
    throw Error(ErrorCode::Usage,
                std::string("the plug-in judges concrete rules only (no ") +
                    kSchemeConditionEntrySymbol + ")",
                "plugin " + path_);
  std::vector<condition::SchemeView> views;
  views.reserve(schemes.size());
  for (const auto& s : schemes) views.push_back(to_view(s));
  return run_guarded(
      views.size(), [&](size_t k) { return scheme_condition_->holds(views[k]); },
      [&](size_t k) { return "scheme " + schemes[k].name; }, eval_timeout);
}

std::vector<bool> ConditionPlugin::run_guarded(size_t count,
                                               const std::function<bool(size_t)>& holds,
                                               const std::function<std::string(size_t)>& describe,
                                               double eval_timeout) const {
  int fds[2];
  if (pipe(fds) != 0)
    throw Error(ErrorCode::Io, std::string("pipe: ") + std::strerror(errno), "plugin " + path_);
  const pid_t pid = fork();
  if (pid < 0)
    throw Error(ErrorCode::Io, std::string("fork: ") + std::strerror(errno), "plugin " + path_);
  if (pid == 0) {  // child
    close(fds[0]);
    // A crash kills the child (a sanitizer's own handlers would turn it into an exit status).
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM}) std::signal(sig, SIG_DFL);
    for (size_t k = 0; k < count; ++k) {
      char c = '0';
      if (eval_timeout > 0) {  // re-armed per rule: SIGALRM (default action: terminate) ends a hang
        itimerval t{};
        t.it_value.tv_sec = static_cast<time_t>(eval_timeout);
        t.it_value.tv_usec =
            static_cast<suseconds_t>((eval_timeout - static_cast<double>(t.it_value.tv_sec)) * 1e6);
        if (t.it_value.tv_sec == 0 && t.it_value.tv_usec == 0) t.it_value.tv_usec = 1;
        setitimer(ITIMER_REAL, &t, nullptr);
      }
      try {
        c = holds(k) ? '1' : '0';
      } catch (const std::exception& e) {
        const std::string msg = std::string("E") + e.what();
        write_all(fds[1], msg.data(), msg.size());
        _exit(3);
      } catch (...) {
        write_all(fds[1], "Ea non-standard exception", 25);
        _exit(3);
      }
      write_all(fds[1], &c, 1);
    }
    _exit(0);
  }
  close(fds[1]);
  std::string got;
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got.append(buf, static_cast<size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const size_t e = got.find('E');
  const size_t done = e == std::string::npos ? got.size() : e;
  auto rule_at = [&](size_t k) { return k < count ? describe(k) : std::string("no rule"); };
  if (e != std::string::npos)
    throw Error(ErrorCode::Usage,
                "the condition threw while evaluating " + rule_at(done) + ": " + got.substr(e + 1),
                "plugin " + path_);
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM && eval_timeout > 0) {
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", eval_timeout);
    throw Error(
        ErrorCode::Usage,
        std::string("the condition did not return within the per-evaluation time limit of ") +
            limit + " s while evaluating " + rule_at(done),
        "plugin " + path_);
  }
  if (WIFSIGNALED(status))
    throw Error(ErrorCode::Usage,
                "the condition crashed (signal " + std::to_string(WTERMSIG(status)) + ", " +
                    strsignal(WTERMSIG(status)) + ") while evaluating " + rule_at(done),
                "plugin " + path_);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || done != count)
    throw Error(ErrorCode::Usage,
                "the condition's process exited (status " +
                    std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                    ") while evaluating " + rule_at(done),
                "plugin " + path_);
  std::vector<bool> out(count);
  for (size_t k = 0; k < count; ++k) out[k] = got[k] == '1';
  return out;
}

}  // namespace gmr::smt
