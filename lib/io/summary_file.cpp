#include "io/summary_file.hpp"

#include <fstream>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace frostwall::io {

namespace fs = std::filesystem;

void write_summary(const fs::path& directory, const summary::Summary& s) {
  write_text_file(directory / "summary.json", summary::to_json(s).dump(2) + "\n");
}

summary::Summary read_summary(const fs::path& directory) {
  const fs::path file = directory / "summary.json";
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception&) {
    throw std::runtime_error(file.string() + ": not valid JSON");
  }
  try {
    return summary::from_json(j);
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

}  // namespace frostwall::io
