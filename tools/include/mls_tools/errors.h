// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The two kinds of error of the command-line tools. A tool's `main` catches them, prints
// `<tool>: error: <what()>` on one line of stderr and exits with `exit_code()`.

#ifndef MLS_TOOLS_ERRORS_H
#define MLS_TOOLS_ERRORS_H

#include <stdexcept>
#include <string>

namespace mls_tools {

/// A bad command line: unknown option, missing or malformed value, unknown extension. Exit code 2.
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
  static constexpr int exit_code = 2;
};

/// A bad input or output file: missing, unreadable, malformed, degenerate, not writable. Exit code 1.
struct Input_error : std::runtime_error {
  using std::runtime_error::runtime_error;
  static constexpr int exit_code = 1;
};

namespace internal {

/// `s` in single quotes, as the messages name files, options and values.
inline std::string quote(const std::string& s) { return "'" + s + "'"; }

} // namespace internal

} // namespace mls_tools

#endif // MLS_TOOLS_ERRORS_H
