// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What bench_duplicates and bench_scale share: each case runs in a child
// process of its own, so that its peak memory is its own, and each writes its
// section of RESULTS.md in place.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_PROCESS_H
#define ENTROPY_SIMPLIFICATION_BENCH_PROCESS_H

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_machine.h"

#include <cerrno>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace bench {

// How a child process ended: `result` is what it sent, valid when `verdict`
// is "ok"; `peak_kib` its maximum resident set size (what `/usr/bin/time -v`
// reports).
template <typename Result>
struct Child_outcome
{
  Result result{};
  std::string verdict;
  long peak_kib = 0;
};

// Runs `measure` in a forked child, which sends its result, a plain struct,
// back through a pipe. `measure` may throw: the child then reports the
// exception's message in `result.failures` (a char array).
template <typename Result>
Child_outcome<Result> run_in_child(const std::function<Result()>& measure)
{
  static_assert(std::is_trivially_copyable<Result>::value, "the result crosses a pipe");
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0)
    throw std::runtime_error("pipe failed");
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0)
    throw std::runtime_error("fork failed");
  if (pid == 0)
  {
    close(pipe_ends[0]);
    Result r{};
    try
    {
      r = measure();
    }
    catch (const std::exception& e)
    {
      std::snprintf(r.failures, sizeof r.failures, "exception: %s", e.what());
    }
    const bool written = write(pipe_ends[1], &r, sizeof r) == ssize_t(sizeof r);
    _exit(written ? EXIT_SUCCESS : EXIT_FAILURE);
  }
  close(pipe_ends[1]);
  Child_outcome<Result> outcome;
  std::size_t got = 0;
  while (got < sizeof outcome.result)
  {
    const ssize_t n = read(pipe_ends[0], reinterpret_cast<char*>(&outcome.result) + got, sizeof outcome.result - got);
    if (n > 0)
      got += std::size_t(n);
    else if (n == 0 || errno != EINTR)
      break;
  }
  close(pipe_ends[0]);
  int status = 0;
  struct rusage usage;
  while (wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR)
      throw std::runtime_error("wait4 failed");
  outcome.peak_kib = usage.ru_maxrss;
  if (WIFSIGNALED(status))
    outcome.verdict = "crashed (signal " + std::to_string(WTERMSIG(status)) + ")";
  else if (got != sizeof outcome.result)
    outcome.verdict = "no result (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  else
    outcome.verdict = outcome.result.failures[0] ? outcome.result.failures : "ok";
  return outcome;
}

// The one-minute load average, to say whether the machine was shared.
inline std::string load_average()
{
  std::ifstream in("/proc/loadavg");
  std::string first;
  return in >> first ? first : std::string("unknown");
}

// The opening of a section: the command, the date, the duration and `how`
// it is run, then the machine and its load.
inline std::string produced_by(const std::string& command, double minutes, const std::string& how,
                               const std::string& load)
{
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  return "Produced by `" + command + "` on " + date + " in " + fixed(minutes, 1) + " minutes" + how +
         ".\n\nMachine: " + machine_description() + "; load average " + load +
         " at the start (other processes shared the cores if above 1).\n\n";
}

// Replaces the section `title` ("## Title") of `file`, up to the next section
// of the same level, or appends it, creating the file if need be; through a
// temporary file, so that a failed write leaves the file as it was.
inline void write_section(const std::string& file, const std::string& title, const std::string& section)
{
  std::string text;
  if (std::ifstream in{ file })
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  const std::size_t start = text.rfind("\n" + title + "\n");
  if (start == std::string::npos)
    text += (text.empty() || text.back() == '\n' ? "\n" : "\n\n") + section;
  else
  {
    const std::size_t end = text.find("\n## ", start + 1);
    text.replace(start + 1, end == std::string::npos ? std::string::npos : end + 1 - (start + 1),
                 section + (end == std::string::npos ? "" : "\n"));
  }
  const std::string temporary = file + ".tmp";
  {
    std::ofstream out(temporary);
    if (!(out << text) || !out.flush())
      throw std::runtime_error("cannot write " + temporary);
  }
  if (std::rename(temporary.c_str(), file.c_str()) != 0)
    throw std::runtime_error("cannot replace " + file);
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_PROCESS_H
