// Progress line drawing: throttled to 4 redraws per second on a terminal (carriage return),
// one line per 10 s when stderr is a file or pipe.
#include "progress_line.hpp"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace rotorsweep::apps {

std::string members_per_second(double members, double seconds) {
  if (!(members > 0) || !(seconds > 0)) return "no members run";
  char text[64];
  std::snprintf(text, sizeof text, "%.1f members/s", members / seconds);
  return text;
}

std::string format_duration(double seconds) {
  char text[64];
  if (seconds < 1)
    std::snprintf(text, sizeof text, "%.0f ms", seconds * 1e3);
  else if (seconds < 60)
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  else if (seconds < 3600)
    std::snprintf(text, sizeof text, "%d min %02d s", int(seconds) / 60, int(seconds) % 60);
  else
    std::snprintf(text, sizeof text, "%d h %02d min", int(seconds) / 3600, (int(seconds) % 3600) / 60);
  return text;
}

ProgressLine::ProgressLine(std::size_t total, bool enabled, std::string unit, std::string stops)
    : total_(total),
      enabled_(enabled),
      terminal_(isatty(STDERR_FILENO) != 0),
      unit_(std::move(unit)),
      stops_(std::move(stops)),
      start_(clock::now()),
      last_draw_(start_) {}

void ProgressLine::update(std::size_t done, std::size_t stops) {
  if (!enabled_) return;
  const auto now = clock::now();
  const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
  if (since_draw < (terminal_ ? 0.25 : 10.0) || done >= total_) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = double(done) / elapsed;
  const std::string eta = rate > 0 ? format_duration(double(total_ - done) / rate) : "?";
  char line[200];
  int width = std::snprintf(line, sizeof line, "  %zu / %zu %s  %.1f %s/s  ETA %s", done, total_,
                            unit_.c_str(), rate, unit_.c_str(), eta.c_str());
  if (stops > 0 && width > 0 && std::size_t(width) < sizeof line)
    width +=
        std::snprintf(line + width, sizeof line - std::size_t(width), "  (%zu %s)", stops, stops_.c_str());
  if (terminal_) {
    std::fprintf(stderr, "\r%s%*s", line, int(last_width_ > std::size_t(width) ? last_width_ - width : 0),
                 "");
    last_width_ = std::size_t(width);
  } else {
    std::fprintf(stderr, "%s\n", line);
  }
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (enabled_ && terminal_ && last_width_ > 0) std::fprintf(stderr, "\r%*s\r", int(last_width_), "");
}

}  // namespace rotorsweep::apps
