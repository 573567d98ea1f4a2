// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A small table-driven parser of long options (`--name value`, `--name=value`, flags), shared by
// the command-line tools, and strict parsers of option values. Every error is a `Usage_error`.

#ifndef MLS_TOOLS_ARGUMENTS_H
#define MLS_TOOLS_ARGUMENTS_H

#include <mls_tools/errors.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <ostream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace mls_tools {

enum class Number_parse { OK, NOT_A_NUMBER, NOT_FINITE };

/// Parses a whole string as a double (no trailing characters, locale independent).
inline Number_parse parse_number(const std::string& text, double& value) {
  const char* first = text.data();
  const char* last = first + text.size();
  if(first != last && *first == '+') ++first; // from_chars does not accept a leading '+'
  if(first == last) return Number_parse::NOT_A_NUMBER;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if(ec == std::errc::result_out_of_range) return Number_parse::NOT_FINITE;
  if(ec != std::errc() || ptr != last) return Number_parse::NOT_A_NUMBER;
  return std::isfinite(value) ? Number_parse::OK : Number_parse::NOT_FINITE;
}

/// Parses a whole string as a finite double.
inline bool parse_double(const std::string& text, double& value) {
  return parse_number(text, value) == Number_parse::OK;
}

/// The value of `option`: a finite number > 0.
inline double parse_positive_double(const std::string& option, const std::string& text) {
  double v = 0;
  if(!parse_double(text, v) || !(v > 0))
    throw Usage_error("option " + option + " needs a finite number > 0, got '" + text + "'");
  return v;
}

/// The value of `option`: an integer in [1, max].
inline int parse_positive_int(const std::string& option, const std::string& text, int max = 1 << 30) {
  const char* first = text.data();
  const char* last = first + text.size();
  if(first != last && *first == '+') ++first;
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if(first == last || ec != std::errc() || ptr != last || v < 1 || v > max)
    throw Usage_error("option " + option + " needs an integer between 1 and " + std::to_string(max) + ", got '" + text + "'");
  return int(v);
}

/// The value of `option` among named `choices`.
template <class T>
T parse_choice(const std::string& option, const std::string& text, const std::vector<std::pair<std::string, T>>& choices) {
  std::string names;
  for(const auto& c : choices) {
    if(c.first == text) return c.second;
    names += (names.empty() ? "" : "|") + c.first;
  }
  throw Usage_error("option " + option + " must be one of " + names + ", got '" + text + "'");
}

/// The long options of a tool. `--help` (and `-h`) is built in.
class Argument_parser {
public:
  using Handler = std::function<void(const std::string&)>;

  /// An option taking a value, shown as `name metavar` in the help.
  void add(std::string name, std::string metavar, std::string help, Handler handler) {
    options_.push_back({std::move(name), std::move(metavar), std::move(help), std::move(handler)});
  }
  /// An option without value.
  void add_flag(std::string name, std::string help, std::function<void()> handler) {
    options_.push_back({std::move(name), std::string(), std::move(help),
                        [h = std::move(handler)](const std::string&) { h(); }});
  }

  /// Calls the handlers of the options in `argv`, in order (the last of a repeated option wins).
  /// \return `false` when `--help` was given (then nothing else is checked)
  bool parse(int argc, const char* const* argv) const {
    for(int i = 1; i < argc; ++i)
      if(std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") return false;
    for(int i = 1; i < argc; ++i) {
      std::string arg = argv[i], value;
      bool has_inline_value = false;
      if(arg.rfind("--", 0) == 0) {
        const auto eq = arg.find('=');
        if(eq != std::string::npos) {
          value = arg.substr(eq + 1);
          arg = arg.substr(0, eq);
          has_inline_value = true;
        }
      } else {
        throw Usage_error("unexpected argument '" + arg + "' (options start with --; see --help)");
      }
      const Option* option = find(arg);
      if(!option) throw Usage_error("unknown option '" + arg + "' (see --help)");
      if(option->metavar.empty()) {
        if(has_inline_value) throw Usage_error("option " + arg + " takes no value");
      } else if(!has_inline_value) {
        // A following option is not a value (negative numbers start with a single '-').
        if(i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0)
          throw Usage_error("option " + arg + " needs a value " + option->metavar);
        value = argv[++i];
      }
      if(!option->metavar.empty() && value.empty())
        throw Usage_error("option " + arg + " needs a value " + option->metavar);
      option->handler(value);
    }
    return true;
  }

  /// One line per option: `  --name METAVAR   help`.
  void print_options(std::ostream& os) const {
    std::size_t width = 6; // "--help"
    for(const auto& o : options_) width = std::max(width, o.name.size() + (o.metavar.empty() ? 0 : 1 + o.metavar.size()));
    const auto line = [&](const std::string& left, const std::string& help) {
      os << "  " << left << std::string(width + 3 - left.size(), ' ') << help << '\n';
    };
    for(const auto& o : options_) line(o.metavar.empty() ? o.name : o.name + " " + o.metavar, o.help);
    line("--help", "print this help and exit");
  }

private:
  struct Option {
    std::string name, metavar, help;
    Handler handler;
  };
  const Option* find(const std::string& name) const {
    for(const auto& o : options_)
      if(o.name == name) return &o;
    return nullptr;
  }
  std::vector<Option> options_;
};

} // namespace mls_tools

#endif // MLS_TOOLS_ARGUMENTS_H
