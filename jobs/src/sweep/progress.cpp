// Sweep progress on stderr (sweep/progress.hpp).
#include "lrchain/jobs/sweep/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

#include <fmt/format.h>

namespace lrchain::jobs::sweep {

namespace {

// "1h02m", "3m05s", "12s".
std::string duration_text(double s) {
  if (!(s >= 0) || s > 1e8) return "?";
  const long t = long(s + 0.5);
  if (t >= 3600) return fmt::format("{}h{:02}m", t / 3600, (t % 3600) / 60);
  if (t >= 60) return fmt::format("{}m{:02}s", t / 60, t % 60);
  return fmt::format("{}s", t);
}

}  // namespace

SweepProgress::SweepProgress(std::size_t total, std::size_t already_done, bool enabled, double plain_every)
    : total_(total),
      start_done_(already_done),
      enabled_(enabled),
      terminal_(::isatty(STDERR_FILENO) != 0),
      plain_every_(plain_every),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void SweepProgress::update(std::size_t done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (since < (terminal_ ? 0.25 : plain_every_)) return;
  last_ = now;
  print(done, false);
}

void SweepProgress::finish(std::size_t done) {
  if (!enabled_) return;
  print(done, true);
}

// Rate and ETA count only the points run by this process since it started.
void SweepProgress::print(std::size_t done, bool final_line) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double ran = double(done - start_done_);
  const double rate = elapsed > 0 ? ran / elapsed : 0;
  const std::string eta = rate > 0 ? duration_text(double(total_ - done) / rate) : "?";
  const std::string line = fmt::format("sweep: {}/{} points ({:.1f}%), {:.2f} points/s, {} {}", done, total_,
                                       total_ ? 100.0 * double(done) / double(total_) : 100.0, rate,
                                       final_line ? "elapsed" : "ETA", final_line ? duration_text(elapsed) : eta);
  if (terminal_)
    std::fprintf(stderr, "\r%-78s%s", line.c_str(), final_line ? "\n" : "");
  else
    std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace lrchain::jobs::sweep
