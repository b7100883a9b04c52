#include "io/atomic_file.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace frostwall::io {

namespace fs = std::filesystem;

void write_atomically(const fs::path& file, const std::function<void(const fs::path&)>& write) {
  // Same directory as the target so the rename stays on one file system
  // (and is therefore atomic); the pid keeps concurrent processes apart.
  fs::path tmp = file;
  tmp += ".tmp-" + std::to_string(::getpid());
  try {
    write(tmp);
    fs::rename(tmp, file);
  } catch (...) {
    std::error_code ignored;  // cleanup must not mask the original error
    fs::remove(tmp, ignored);
    throw;
  }
}

void write_text_file(const fs::path& file, const std::string& text) {
  write_atomically(file, [&](const fs::path& tmp) {
    // Binary mode: the text is written byte for byte, no newline translation.
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open for writing: " + tmp.string());
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();  // close explicitly so a failed flush is seen below
    if (!out) throw std::runtime_error("error writing: " + tmp.string());
  });
}

}  // namespace frostwall::io
