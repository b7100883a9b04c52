// Output files appear complete or not at all: written to "<name>.tmp-<pid>"
// in the same directory, then renamed over the final name.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace frostwall::io {

// Calls write(temporary_path), then renames it to `file`. If write throws,
// the temporary is removed and the exception passes on.
void write_atomically(const std::filesystem::path& file,
                      const std::function<void(const std::filesystem::path&)>& write);

// Text convenience over write_atomically.
void write_text_file(const std::filesystem::path& file, const std::string& text);

}  // namespace frostwall::io
