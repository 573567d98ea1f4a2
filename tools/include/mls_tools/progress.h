// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A progress bar on stderr for the command-line tools, drawn only when stderr is a terminal.
// `callback()` fits the `callback` named parameter of the package's functions.

#ifndef MLS_TOOLS_PROGRESS_H
#define MLS_TOOLS_PROGRESS_H

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

#include <unistd.h>

namespace mls_tools {

/// `true` when stderr is a terminal (progress bars are pointless in logs and pipes).
inline bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

class Progress_bar {
public:
  /// \param label printed before the bar
  /// \param enabled draw nothing when `false` (e.g. `--quiet`, or stderr is not a terminal)
  Progress_bar(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled) {}
  ~Progress_bar() { finish(); }

  /// Draws the bar at `fraction` (0 to 1), at most every 0.1 s and whenever the percentage changes.
  void update(double fraction) {
    if(!enabled_ || finished_) return;
    fraction = std::clamp(fraction, 0., 1.);
    const int percent = int(fraction * 100.);
    const auto now = std::chrono::steady_clock::now();
    if(percent == last_percent_ || (percent < 100 && now - last_draw_ < std::chrono::milliseconds(100))) return;
    last_percent_ = percent;
    last_draw_ = now;
    const int width = 40, filled = int(fraction * width);
    std::string bar(std::size_t(filled), '#');
    bar.resize(std::size_t(width), ' ');
    std::fprintf(stderr, "\r%s [%s] %3d%%", label_.c_str(), bar.c_str(), percent);
    std::fflush(stderr);
    drawn_ = true;
  }

  /// Erases the bar, so that the next line of stderr starts clean.
  void finish() {
    if(finished_) return;
    finished_ = true;
    if(drawn_) {
      std::fprintf(stderr, "\r%s\r", std::string(label_.size() + 48, ' ').c_str());
      std::fflush(stderr);
    }
  }

  /// A callback for the package's functions (`callback` named parameter): never cancels.
  std::function<bool(double)> callback() {
    return [this](double fraction) {
      update(fraction);
      return true;
    };
  }

private:
  std::string label_;
  bool enabled_, drawn_ = false, finished_ = false;
  int last_percent_ = -1;
  std::chrono::steady_clock::time_point last_draw_{};
};

} // namespace mls_tools

#endif // MLS_TOOLS_PROGRESS_H
