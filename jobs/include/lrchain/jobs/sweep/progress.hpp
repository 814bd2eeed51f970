#pragma once
// Progress of a sweep on stderr: points done/total, rate and ETA; one line redrawn in place on a
// terminal, else a plain line every `plain_every` seconds.
#include <chrono>
#include <cstddef>

namespace lrchain::jobs::sweep {

class SweepProgress {
 public:
  SweepProgress(std::size_t total, std::size_t already_done, bool enabled, double plain_every = 10);
  void update(std::size_t done);  // points finished in all (including those resumed)
  void finish(std::size_t done);  // the last line

 private:
  void print(std::size_t done, bool final_line);
  std::size_t total_, start_done_;
  bool enabled_, terminal_;
  double plain_every_;
  std::chrono::steady_clock::time_point start_, last_;
  bool drawn_ = false;
};

}  // namespace lrchain::jobs::sweep
