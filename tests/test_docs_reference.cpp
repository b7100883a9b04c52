// The project-file reference (docs/reference/) names every key the loaders
// accept. The keys are read from the loaders' own source: every string in
// a Node::object({...}) list (the keys an object may have; any other is
// refused as unknown) and every key read as n["key"]. Each must be the last
// part of some entry heading, ### `path.to.key`, in docs/reference/*.md.
// A key added to a loader without its entry fails here.
#include <catch2/catch.hpp>

#include "text_file.hpp"
#include "paths.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using frostwall::test::read_text;

// The keys the loaders read, with the file that reads each.
std::set<std::pair<std::string, std::string>> accepted_keys() {
  const fs::path src = FROSTWALL_SOURCE_DIR;
  std::vector<fs::path> loaders = {src / "lib" / "study" / "study_file.cpp"};
  for (const auto& f : fs::directory_iterator(src / "lib" / "project"))
    if (f.path().extension() == ".cpp") loaders.push_back(f.path());
  const std::regex list(R"(object\(\{([^}]*)\}\))"), literal(R"re("([A-Za-z_][A-Za-z0-9_]*)")re"),
      read_key(R"re(\[\s*"([A-Za-z_][A-Za-z0-9_]*)"\s*\])re"), ring_angle(R"re(read_ring\([^,]+,\s*"([A-Za-z_]+)")re");
  std::set<std::pair<std::string, std::string>> keys;
  for (const auto& file : loaders) {
    const std::string text = read_text(file), name = file.filename().string();
    for (auto it = std::sregex_iterator(text.begin(), text.end(), list); it != std::sregex_iterator(); ++it) {
      const std::string inside = (*it)[1];
      for (auto k = std::sregex_iterator(inside.begin(), inside.end(), literal); k != std::sregex_iterator(); ++k)
        keys.insert({(*k)[1], name});
    }
    for (const auto* pattern : {&read_key, &ring_angle})
      for (auto it = std::sregex_iterator(text.begin(), text.end(), *pattern); it != std::sregex_iterator(); ++it)
        keys.insert({(*it)[1], name});
  }
  return keys;
}

// The last part of every ### `a.b[].c` heading.
std::set<std::string> documented_keys() {
  std::set<std::string> keys;
  const std::regex heading(R"(\n### `([^`]+)`)");
  for (const auto& f : fs::directory_iterator(fs::path(FROSTWALL_SOURCE_DIR) / "docs" / "reference")) {
    if (f.path().extension() != ".md") continue;
    const std::string text = "\n" + read_text(f.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), heading); it != std::sregex_iterator(); ++it) {
      std::string path = (*it)[1];
      while (path.size() > 2 && path.ends_with("[]")) path.resize(path.size() - 2);
      const auto dot = path.find_last_of('.');
      keys.insert(dot == std::string::npos ? path : path.substr(dot + 1));
    }
  }
  return keys;
}

}  // namespace

TEST_CASE("The project-file reference names every key the loaders accept", "[shared][docs]") {
  const auto accepted = accepted_keys();
  const auto documented = documented_keys();
  REQUIRE(accepted.size() > 150);
  REQUIRE(documented.size() > 150);
  for (const auto& [key, file] : accepted) {
    INFO(file << " reads \"" << key << "\": give it an entry ### `...." << key << "` in docs/reference/");
    CHECK(documented.count(key) == 1);
  }
}
