// A minimal test harness: each test is a function registered with MLS_TEST; checks count
// failures without stopping, and main() prints the closing line `N passed, M failed`.
#ifndef CGAL_MLS_PROJECTION_TEST_FRAMEWORK_H
#define CGAL_MLS_PROJECTION_TEST_FRAMEWORK_H

#include <Eigen/Core>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace mls_test {

/// D draws of `dist`, in the order x, y, z. Written `V(dist(gen), dist(gen), dist(gen))` (or
/// `a + dist(gen), b + dist(gen)`), the order is unspecified (gcc draws z first, clang x), and a
/// test would check other data with each compiler.
template <int D = 3, class Distribution, class Generator>
Eigen::Matrix<double, D, 1> random_vector(Distribution& dist, Generator& gen) {
  Eigen::Matrix<double, D, 1> v;
  for(int k = 0; k < D; ++k) v[k] = dist(gen);
  return v;
}

struct Test {
  const char* name;
  std::function<void()> body;
};
inline std::vector<Test>& registry() {
  static std::vector<Test> tests;
  return tests;
}
inline int& failures() {
  static int n = 0;
  return n;
}
struct Registrar {
  Registrar(const char* name, std::function<void()> body) { registry().push_back({name, std::move(body)}); }
};

inline std::string fmt(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

inline void check(bool ok, const char* expr, const char* file, int line, const std::string& what = {}) {
  if(ok) return;
  ++failures();
  std::cerr << file << ":" << line << ": check failed: " << expr << (what.empty() ? "" : "  [" + what + "]") << "\n";
}

// Runs the tests whose name contains argv[1] (all without argument), except those named in the
// environment variable MLS_TEST_SKIP (names separated by commas), which are reported as skipped.
// Each test's line gives its wall time (what the sanitizer stages' skip lists are chosen by).
inline int run_all(int argc, char** argv) {
  int passed = 0, failed = 0;
  const char* skip = std::getenv("MLS_TEST_SKIP");
  const std::string skipped = "," + std::string(skip ? skip : "") + ",";
  for(const Test& t : registry()) {
    if(argc > 1 && std::strstr(t.name, argv[1]) == nullptr) continue;
    if(skipped.find("," + std::string(t.name) + ",") != std::string::npos) {
      std::cout << "[skip] " << t.name << " (MLS_TEST_SKIP)" << std::endl;
      continue;
    }
    const int before = failures();
    const auto start = std::chrono::steady_clock::now();
    t.body();
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    const bool ok = failures() == before;
    std::cout << (ok ? "[ ok ] " : "[FAIL] ") << t.name << " (" << fmt(seconds.count()) << " s)" << std::endl;
    (ok ? passed : failed)++;
  }
  std::cout << passed << " passed, " << failed << " failed" << std::endl;
  return failed == 0 && passed > 0 ? 0 : 1;
}

} // namespace mls_test

#define MLS_CONCAT2(a, b) a##b
#define MLS_CONCAT(a, b) MLS_CONCAT2(a, b)
#define MLS_TEST(name)                                                                   \
  static void name();                                                                    \
  static mls_test::Registrar MLS_CONCAT(registrar_, name)(#name, &name);                 \
  static void name()
#define MLS_CHECK(cond) mls_test::check(static_cast<bool>(cond), #cond, __FILE__, __LINE__)
#define MLS_CHECK_MSG(cond, msg) mls_test::check(static_cast<bool>(cond), #cond, __FILE__, __LINE__, (msg))
// |a - b| <= tol, printing the values when it fails.
#define MLS_CHECK_NEAR(a, b, tol)                                                                      \
  mls_test::check(std::abs((a) - (b)) <= (tol), #a " ~ " #b, __FILE__, __LINE__,                    \
                  mls_test::fmt(a) + " vs " + mls_test::fmt(b) + " tol " + mls_test::fmt(tol))
#define MLS_CHECK_LE(a, b)                                                                             \
  mls_test::check((a) <= (b), #a " <= " #b, __FILE__, __LINE__,                                      \
                  mls_test::fmt(a) + " > " + mls_test::fmt(b))

#endif
