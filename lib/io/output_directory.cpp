#include "io/output_directory.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fmt/core.h>
#include <unistd.h>

#include "project/project.hpp"

namespace frostwall::io {

namespace fs = std::filesystem;

void check_output_directory(const std::string& directory) {
  // The nearest ancestor that exists must be a directory we may write in;
  // nothing is created here (bad input writes nothing).
  std::error_code ec;
  fs::path existing = fs::absolute(fs::path(directory).lexically_normal(), ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  const char* reason = nullptr;
  if (!fs::is_directory(existing, ec)) reason = std::strerror(ENOTDIR);
  else if (access(existing.c_str(), W_OK | X_OK) != 0) reason = std::strerror(errno);
  if (reason) throw project::ProjectError({fmt::format("output.directory: cannot create '{}': {}", directory, reason)});
}

}  // namespace frostwall::io
