// What a long run shows: a progress bar on a terminal, and the peak memory
// for the closing summary.

#ifndef ENTROPY_SIMPLIFY_PROGRESS_H
#define ENTROPY_SIMPLIFY_PROGRESS_H

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace entropy_simplify {

// Draws a bar on stderr, only when stderr is a terminal and the run has
// lasted a second: short runs and logs stay clean.
class Progress_bar
{
public:
  explicit Progress_bar(bool wanted) : enabled_(wanted && ::isatty(STDERR_FILENO)) {}

  // The library's callback: `done` is the fraction of the work done.
  bool operator()(double done)
  {
    if (!enabled_)
      return true;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const int percent = int(done * 100.);
    if (elapsed < 1. || percent == last_percent_)
      return true;
    last_percent_ = percent;
    const int width = 40, filled = percent * width / 100;
    std::fprintf(stderr, "\r[%s%s] %3d%%  %.0f s ", std::string(std::size_t(filled), '#').c_str(),
                 std::string(std::size_t(width - filled), '.').c_str(), percent, elapsed);
    std::fflush(stderr);
    return true;
  }

  // Erases the bar, if drawn.
  void finish()
  {
    if (last_percent_ >= 0)
      std::fprintf(stderr, "\r%60s\r", "");
    last_percent_ = -1;
  }

private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  Clock::time_point start_ = Clock::now();
  int last_percent_ = -1;
};

// The process's peak resident memory so far, in MiB.
inline double peak_memory_mib()
{
  struct rusage usage;
  ::getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_PROGRESS_H
