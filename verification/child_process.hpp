// Runs a program as a child process with a wall-time limit, capturing its output, exit status and
// peak memory (wait4's ru_maxrss): the adversarial suite asks of every scene that it neither
// crashes, nor hangs past its limit, nor takes more memory than its estimate.
#pragma once
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace blaze::test {

struct ChildResult {
  int status = -1;        // exit status; -1 when killed by a signal (signal says which)
  int signal = 0;
  bool timed_out = false;  // killed by us at the limit
  double peak_bytes = 0;   // resident set at its largest
  std::string output;      // stdout and stderr, interleaved
};

// `env`: variables set in the child only.
inline ChildResult run_child(const std::vector<std::string>& argv, double limit_s,
                             const std::vector<std::pair<std::string, std::string>>& env = {}) {
  ChildResult r;
  int fds[2];
  if (pipe(fds) != 0) return r;
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fds[1], 1);
    dup2(fds[1], 2);
    close(fds[0]);
    close(fds[1]);
    for (const auto& [name, value] : env) setenv(name.c_str(), value.c_str(), 1);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  close(fds[1]);
  const auto start = std::chrono::steady_clock::now();
  char buf[4096];
  for (;;) {
    const double left = limit_s - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (left <= 0) {
      kill(pid, SIGKILL);
      r.timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left * 1000) + 1) <= 0) continue;
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n <= 0) break;  // the child closed its output: it is ending
    r.output.append(buf, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int st = 0;
  rusage use{};
  wait4(pid, &st, 0, &use);
  r.peak_bytes = static_cast<double>(use.ru_maxrss) * 1024;
  if (WIFEXITED(st)) r.status = WEXITSTATUS(st);
  if (WIFSIGNALED(st)) r.signal = WTERMSIG(st);
  return r;
}

}  // namespace blaze::test
