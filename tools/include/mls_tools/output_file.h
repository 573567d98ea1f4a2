// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// An output file written atomically: the text goes to a temporary file created next to the
// target (so creating it also checks, before any work, that the target can be written), which
// is renamed onto the target by `commit()`. If the tool fails, throws, or is interrupted
// (SIGINT, SIGTERM, SIGHUP), the temporary file is removed: no half-written file is ever left.

#ifndef MLS_TOOLS_OUTPUT_FILE_H
#define MLS_TOOLS_OUTPUT_FILE_H

#include <mls_tools/errors.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace mls_tools {

namespace internal {
// The temporary files to remove on a signal (a few at a time, e.g. an output and a side output;
// async-signal-safe access only).
constexpr int max_pending_temps = 4;
inline char pending_temp_path[max_pending_temps][4096] = {};
inline volatile std::sig_atomic_t has_pending_temp[max_pending_temps] = {};

extern "C" inline void remove_pending_temp_and_exit(int sig) {
  for(int i = 0; i < max_pending_temps; ++i)
    if(has_pending_temp[i]) ::unlink(pending_temp_path[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}
} // namespace internal

class Atomic_output_file {
public:
  /// Creates the temporary file next to `path`. \throws Input_error when it cannot be created.
  explicit Atomic_output_file(const std::string& path) : path_(path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if(fs::is_directory(path, ec)) throw Input_error("cannot write '" + path + "': it is a directory");
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::string tmpl = (dir / ("." + target.filename().string() + ".tmp.XXXXXX")).string();
    std::vector<char> buffer(tmpl.begin(), tmpl.end());
    buffer.push_back('\0');
    const int fd = ::mkstemp(buffer.data());
    if(fd < 0) throw Input_error("cannot write '" + path + "': " + std::strerror(errno));
    temp_.assign(buffer.data());
    // mkstemp creates the file with mode 0600: give it the usual mode of a new file.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
    for(int i = 0; i < internal::max_pending_temps && slot_ < 0; ++i)
      if(!internal::has_pending_temp[i] && temp_.size() < sizeof(internal::pending_temp_path[i])) slot_ = i;
    if(slot_ >= 0) {
      std::strcpy(internal::pending_temp_path[slot_], temp_.c_str());
      internal::has_pending_temp[slot_] = 1;
      for(int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, internal::remove_pending_temp_and_exit);
    }
    stream_.open(temp_, std::ios::out | std::ios::trunc);
    if(!stream_) {
      discard();
      throw Input_error("cannot write '" + path + "'");
    }
  }

  Atomic_output_file(const Atomic_output_file&) = delete;
  Atomic_output_file& operator=(const Atomic_output_file&) = delete;
  ~Atomic_output_file() { discard(); }

  std::ostream& stream() { return stream_; }
  const std::string& path() const { return path_; }

  /// Flushes and closes the temporary file and renames it onto the target.
  /// \throws Input_error (and removes the temporary file) when writing failed
  void commit() {
    stream_.flush();
    const bool written = bool(stream_);
    stream_.close();
    if(!written || stream_.fail()) {
      discard();
      throw Input_error("error while writing '" + path_ + "'");
    }
    if(std::rename(temp_.c_str(), path_.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      discard();
      throw Input_error("cannot write '" + path_ + "': " + reason);
    }
    release_slot();
    temp_.clear();
  }

  /// Removes the temporary file (nothing after `commit()`).
  void discard() {
    if(temp_.empty()) return;
    release_slot();
    if(stream_.is_open()) stream_.close();
    std::remove(temp_.c_str());
    temp_.clear();
  }

private:
  void release_slot() {
    if(slot_ >= 0) internal::has_pending_temp[slot_] = 0;
    slot_ = -1;
  }

  std::string path_, temp_;
  int slot_ = -1; // in internal::pending_temp_path
  std::ofstream stream_;
};

} // namespace mls_tools

#endif // MLS_TOOLS_OUTPUT_FILE_H
