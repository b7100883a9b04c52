// The layers of lib/ (docs/architecture.md): lib/CMakeLists.txt declares
// each folder's library and the folders it may include. Here the declared
// order is read back and held against the code: every folder depends only
// on folders declared before it (so no circle), and every #include "x/..."
// in lib/ names its own folder or one it may reach.
#include <catch2/catch.hpp>

#include "text_file.hpp"
#include "paths.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using frostwall::test::read_text;

struct Layer {
  std::string name;
  std::vector<std::string> depends;
};

// frostwall_layer(NAME ... DEPENDS a b c [LIBS ...] [PRIVATE_LIBS ...]), in file order.
std::vector<Layer> declared_layers() {
  const std::string text = read_text(fs::path(FROSTWALL_SOURCE_DIR) / "lib" / "CMakeLists.txt");
  std::vector<Layer> layers;
  const std::regex call(R"(\nfrostwall_layer\(([^)]*)\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator(); ++it) {
    std::istringstream words((*it)[1].str());
    Layer layer;
    words >> layer.name;
    bool in_depends = false;
    for (std::string w; words >> w;) {
      if (w == "DEPENDS") in_depends = true;
      else if (w == "LIBS" || w == "PRIVATE_LIBS") in_depends = false;
      else if (in_depends) layer.depends.push_back(w);
    }
    layers.push_back(layer);
  }
  return layers;
}

}  // namespace

TEST_CASE("The layers hold: lib/ includes only downward, as lib/CMakeLists.txt declares", "[shared][architecture]") {
  const auto layers = declared_layers();
  REQUIRE(layers.size() >= 15);
  // Each dependency is declared earlier: the graph has no circle.
  std::map<std::string, std::set<std::string>> reach;  // folder -> every folder below it
  for (const auto& layer : layers) {
    INFO(layer.name);
    for (const auto& dep : layer.depends) {
      INFO("depends on " << dep);
      REQUIRE(reach.count(dep) == 1);
      reach[layer.name].insert(dep);
      reach[layer.name].insert(reach[dep].begin(), reach[dep].end());
    }
    reach[layer.name];
  }
  // Every folder of lib/ is a declared layer, and each include goes down.
  const fs::path lib = fs::path(FROSTWALL_SOURCE_DIR) / "lib";
  const std::regex include(R"(#include\s+"([a-z_]+)/[^"]+")");
  std::size_t includes = 0;
  for (const auto& folder : fs::directory_iterator(lib)) {
    if (!folder.is_directory()) continue;
    const std::string name = folder.path().filename();
    INFO("folder lib/" << name);
    REQUIRE(reach.count(name) == 1);
    for (const auto& file : fs::directory_iterator(folder)) {
      const std::string text = read_text(file.path());
      for (auto it = std::sregex_iterator(text.begin(), text.end(), include); it != std::sregex_iterator(); ++it) {
        const std::string target = (*it)[1];
        if (!fs::is_directory(lib / target)) continue;  // a system header in a subfolder
        ++includes;
        INFO(file.path().filename().string() << ": " << (*it)[0].str());
        CHECK((target == name || reach[name].count(target) == 1));
      }
    }
  }
  CHECK(includes > 300);
  // The engines stand side by side: none reaches another's folder, except
  // mechanics, which runs the freezing engine's heat run with its solid.
  CHECK(reach["freezing"].count("mechanics") == 0);
  CHECK(reach["freezing"].count("cfd_dem") == 0);
  CHECK(reach["cfd_dem"].count("freezing") == 0);
  CHECK(reach["cfd_dem"].count("mechanics") == 0);
  // The report is built from a run's files: it reaches no engine and no run.
  for (const char* above : {"freezing", "mechanics", "cfd_dem", "run", "study"})
    CHECK(reach["report"].count(above) == 0);
  // The project's plain structs reach nothing.
  CHECK(reach["project"].empty());
}
