#include "io/output_directory.hpp"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fmt/core.h>
#include <system_error>

#include "project/project.hpp"

namespace frostwall::io {

namespace fs = std::filesystem;

void check_output_directory(const std::string& directory) {
  // Made and taken away again (bad input writes nothing): only making it
  // proves it can be made (permissions pass for root where the file system
  // refuses, as under /proc).
  std::error_code ec;
  const fs::path target = fs::absolute(fs::path(directory).lexically_normal(), ec);
  fs::path existing = target;
  while (!existing.empty() && !fs::exists(existing, ec) && existing.has_parent_path() &&
         existing != existing.parent_path())
    existing = existing.parent_path();
  std::string reason;
  if (!fs::is_directory(existing, ec)) reason = std::make_error_code(std::errc::not_a_directory).message();
  else if (existing != target) {
    fs::create_directories(target, ec);
    if (ec) reason = ec.message();
    for (fs::path made = target; made != existing && made.has_parent_path(); made = made.parent_path())
      fs::remove(made, ec);  // what this check made (empty), deepest first
  } else {
    // It exists: a file written in it and removed proves it takes files.
    const fs::path probe = target / ".frostwall-write-check";
    if (FILE* f = std::fopen(probe.c_str(), "w")) std::fclose(f), fs::remove(probe, ec);
    else reason = std::error_code(errno, std::generic_category()).message();
  }
  if (!reason.empty())
    throw project::ProjectError({fmt::format("output.directory: cannot create '{}': {}", directory, reason)});
}

}  // namespace frostwall::io
