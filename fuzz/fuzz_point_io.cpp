// libFuzzer harness of the command-line tools' point readers (tools/include/mls_tools/point_io.h).
//
// The first byte chooses the format (.xyz, .pwn, .ply, .off); the other bytes are the file, written
// to a private temporary file that `read_point_file` then reads, as the tools do. Allowed outcomes:
// a point cloud (then checked: dimension 2 or 3, every coordinate finite, one normal per point when
// it has normals), or an `Input_error` / `Usage_error`, which the tools print as a one-line error.
// Anything else is a finding: a crash or sanitizer report, an exception of another type (the tools
// would print a message meant for programmers), a hang (libFuzzer's -timeout) or an allocation
// beyond -rss_limit_mb.
//
// Built only with -DMLS_PROJECTION_BUILD_FUZZERS=ON and clang; see fuzz/README.md.

#include <mls_tools/errors.h>
#include <mls_tools/point_io.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_point_io: %s\n", what.c_str());
  std::abort();
}

std::string temporary_path(const char* extension) {
  const char* dir = std::getenv("TMPDIR");
  static const std::string base = std::string(dir && *dir ? dir : "/tmp") + "/fuzz_point_io." + std::to_string(::getpid());
  return base + extension;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if(size < 1) return 0;
  static const char* const extensions[] = {".xyz", ".pwn", ".ply", ".off"};
  const std::string path = temporary_path(extensions[data[0] % 4]);
  {
    std::ofstream os(path, std::ios::binary | std::ios::trunc);
    os.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  try {
    const mls_tools::Point_cloud cloud = mls_tools::read_point_file(path);
    if(cloud.dimension != 2 && cloud.dimension != 3) finding("dimension " + std::to_string(cloud.dimension));
    if(cloud.points.empty()) finding("no points but no error");
    if(cloud.has_normals != !cloud.normals.empty() || (cloud.has_normals && cloud.normals.size() != cloud.size()))
      finding("normals do not match the points");
    for(std::size_t i = 0; i < cloud.size(); ++i)
      for(int k = 0; k < 3; ++k)
        if(!std::isfinite(cloud.points[i][k]) || (cloud.has_normals && !std::isfinite(cloud.normals[i][k])))
          finding("non-finite coordinate in a point cloud read without error");
    try {
      mls_tools::check_point_cloud(cloud, std::size_t(cloud.dimension + 1), "fuzz input");
    } catch(const mls_tools::Input_error&) {
    }
  } catch(const mls_tools::Input_error& e) {
    if(std::string(e.what()).find('\n') != std::string::npos) finding(std::string("multi-line message: ") + e.what());
  } catch(const mls_tools::Usage_error&) {
  }
  std::remove(path.c_str());
  return 0;
}
