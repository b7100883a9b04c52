// A fresh, empty directory for one test, removed again at the end of the
// scope, so parallel ctest runs and leftovers cannot interfere.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace frostwall::test {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& prefix = "frostwall-test") {
    for (int attempt = 0;; ++attempt) {
      path = std::filesystem::temp_directory_path() /
             (prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(attempt));
      if (std::filesystem::create_directory(path)) break;  // false: it already existed
    }
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

}  // namespace frostwall::test
