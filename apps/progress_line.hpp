// The progress line of long runs on stderr: items (members, raster rows) done / total, per second and the
// estimated time left; redrawn in place on a terminal, one line every 10 s otherwise.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace rotorsweep::apps {

class ProgressLine {
 public:
  /// `stops`: what update's second count says (a row member's periods, a slider member's samples).
  ProgressLine(std::size_t total, bool enabled, std::string unit = "members",
               std::string stops = "periods closed");
  /// Reports `done` items (and, where it helps with long members, the stops they closed);
  /// draws only if enough time has passed since the last draw.
  void update(std::size_t done, std::size_t stops = 0);
  /// Clears the in-place line (terminal) before the closing message.
  void finish();

 private:
  using clock = std::chrono::steady_clock;
  std::size_t total_;
  bool enabled_, terminal_;
  std::string unit_, stops_;
  clock::time_point start_, last_draw_;
  std::size_t last_width_ = 0;
};

/// "3 min 12 s", "12.3 s", "850 ms".
std::string format_duration(double seconds);

/// "123.4 members/s", or "no members run" when none were (no NaN or inf from 0/0).
std::string members_per_second(double members, double seconds);

}  // namespace rotorsweep::apps
