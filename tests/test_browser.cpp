// Story: the pages open in a real browser. Headless Chromium (Debian's
// chromium, as CI installs it) renders a coarse study's study.html and one
// variant's report.html to PNG screenshots of the requested size that are
// not blank, and its DOM dump shows every image inline (data URIs). The
// pages and screenshots stay in build/test-artifacts/browser/ (CI
// artifacts). No chromium is a failure, not a skip: CI installs it. A
// small PD plate and a small frost run show their own report: the method
// in the title, their physics' cards, temperature maps, no shaft parts.
#include <catch2/catch.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include "study/study_report.hpp"
#include "shipped_run.hpp"
#include "temp_dir.hpp"
#include "paths.hpp"

using namespace frostwall;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path artifacts = fs::path(FROSTWALL_ARTIFACT_DIR) / "browser";

const std::string chromium_flags =
    "--headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking --hide-scrollbars";

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

// Chromium's own output goes to <log>.log beside the screenshots; its
// profile to a scratch folder.
std::string chromium(const std::string& arguments, const fs::path& page, const std::string& log) {
  const test::TempDir profile("frostwall-chromium");
  const std::string command = "timeout 120 chromium " + chromium_flags + " --user-data-dir='" + profile.path.string() +
                              "' " + arguments + " 'file://" + page.string() + "' 2>'" +
                              (artifacts / (log + ".log")).string() + "'";
  std::string out;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 65536> buffer{};
    for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) out.append(buffer.data(), n);
    ::pclose(pipe);
  }
  return out;
}

struct Screenshot {
  int width = 0, height = 0;
  double luminance_sd = 0.0;  // spread of the pixels' brightness
  double non_white = 0.0;     // fraction of pixels that are not page white
};

Screenshot screenshot(const fs::path& page, const fs::path& png, int width, int height) {
  fs::remove(png);
  chromium(fmt::format("--screenshot='{}' --window-size={},{}", png.string(), width, height), page,
           png.stem().string());
  Screenshot s;
  if (!fs::exists(png)) return s;
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(png.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  s.width = dims[0], s.height = dims[1];
  const int channels = image->GetNumberOfScalarComponents();
  const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
  double sum = 0, sum2 = 0, coloured = 0;
  const std::size_t n = std::size_t(dims[0]) * std::size_t(dims[1]);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char* px = p + i * channels;
    const double y = 0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2];
    sum += y, sum2 += y * y;
    coloured += (px[0] < 245 || px[1] < 245 || px[2] < 245);
  }
  s.luminance_sd = std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
  s.non_white = coloured / n;
  return s;
}

// The start of the src (or href) of every <img> and SVG <image> in a DOM
// dump (scanned by hand: std::regex recurses per character and overflows
// the stack on megabytes of base64).
std::vector<std::string> image_sources(const std::string& dom) {
  std::vector<std::string> sources;
  for (const auto& [tag, attribute] : {std::pair{"<img", " src=\""}, std::pair{"<image", " href=\""}}) {
    const std::string t = tag;
    for (std::size_t pos = 0; (pos = dom.find(t, pos)) != std::string::npos; pos += t.size()) {
      const char next = dom[pos + t.size()];
      if (next != ' ' && next != '>' && next != '/') continue;  // <imagex>, <img> vs <image>
      const std::size_t end = dom.find('>', pos);
      const std::size_t at = dom.find(attribute, pos);
      sources.push_back(at < end ? dom.substr(at + std::string(attribute).size(), 40) : std::string("(none)"));
    }
  }
  return sources;
}

}  // namespace

TEST_CASE("Headless Chromium renders report.html and study.html: right size, not blank, images inline",
          "[shared][browser]") {
  INFO("chromium is required: CI installs it from .ci/setup (apt-get install chromium)");
  REQUIRE(have_chromium());
  fs::remove_all(artifacts);
  fs::create_directories(artifacts);

  // A coarse two-variant study: its study.html and one variant's report.html.
  const fs::path projects = fs::path(FROSTWALL_SOURCE_DIR) / "projects";
  json s = {{"name", "Browser check: single vs four-hole (coarse)"},
            {"base", "single_ring_sand.json"},
            {"output", {{"directory", (artifacts / "study").string()}}},
            {"patch", json::parse(R"({ "numerics": { "spacing": 0.1 }, "time": { "end": 12, "snapshots": [4, 8, 12] },
                                       "monitoring": [ { "name": "C1", "r": 5.0, "theta_deg": 6.923 } ] })")},
            {"variants", json::parse(R"([ { "name": "single", "patch": {} },
               { "name": "four-hole", "patch": { "layout": { "pattern": "four-hole", "inner_ring": { "radius": 4.2 } } } } ])")}};
  const auto study = study::parse_study(s.dump(), projects, "browser study");
  study::StudyOptions options;
  options.jobs = 2;
  const auto run = study::run_and_write_study(study, options);
  for (const auto& v : run.variants) {
    INFO(v.name << (v.errors.empty() ? "" : ": " + v.errors.front()));
    REQUIRE(v.ok);
  }

  const struct {
    fs::path page;
    const char* png;
    int width, height;
    std::size_t images;
  } pages[] = {
      {artifacts / "study" / "single" / "report.html", "report.png", 1200, 4200, 3},
      {artifacts / "study" / "study.html", "study.png", 1200, 1400, 0},
  };
  for (const auto& page : pages) {
    INFO(page.page);
    const Screenshot shot = screenshot(page.page, artifacts / page.png, page.width, page.height);
    CHECK(shot.width == page.width);
    CHECK(shot.height == page.height);
    CHECK(shot.luminance_sd > 20.0);  // text, tables, maps: far from a flat page
    CHECK(shot.non_white > 0.03);

    const std::string dom = chromium("--dump-dom", page.page, page.png + std::string(".dom"));
    std::ofstream(artifacts / (std::string(page.png) + ".dom.html")) << dom;
    CHECK(dom.find("</html>") != std::string::npos);
    const auto sources = image_sources(dom);
    CHECK(sources.size() == page.images);
    for (const auto& src : sources) CHECK(src.rfind("data:image/png;base64,", 0) == 0);
  }
}

namespace {

// The page in the browser: not blank; the DOM names the method and shows
// the cards, every image inline, the temperature maps, and no shaft parts.
void check_plain_page(const fs::path& page, const std::string& png, const std::string& method,
                      const std::vector<std::string>& cards, std::size_t temperature_maps) {
  const Screenshot shot = screenshot(page, artifacts / png, 1200, 3000);
  CHECK(shot.width == 1200);
  CHECK(shot.luminance_sd > 20.0);
  CHECK(shot.non_white > 0.03);
  const std::string dom = chromium("--dump-dom", page, png + ".dom");
  std::ofstream(artifacts / (png + ".dom.html")) << dom;
  REQUIRE(dom.find("</html>") != std::string::npos);
  CHECK(dom.find(method) != std::string::npos);
  for (const auto& c : cards) {
    INFO("card " << c);
    CHECK(dom.find("<div class=\"label\">" + c) != std::string::npos);
  }
  std::size_t maps = 0;
  for (std::size_t pos = 0; (pos = dom.find("alt=\"temperature map", pos)) != std::string::npos; ++pos) ++maps;
  CHECK(maps == temperature_maps);
  for (const auto& src : image_sources(dom)) CHECK(src.rfind("data:image/png;base64,", 0) == 0);
  for (const char* absent :
       {"Pipe temperature", "Design targets", "Design check", "Closure of the frozen wall", "Wendland"}) {
    INFO(absent);
    CHECK(dom.find(absent) == std::string::npos);
  }
}

}  // namespace

TEST_CASE("Headless Chromium shows a PD plate's report: the method, its cards, temperature maps, no shaft parts",
          "[shared][browser][pd]") {
  REQUIRE(have_chromium());
  fs::create_directories(artifacts);
  const fs::path out = artifacts / "plate";
  fs::remove_all(out);
  // plate_cooling at 0.5 mm (400 particles), 100 s, two snapshots.
  test::run_shipped(
      "plate_cooling.json",
      {{"numerics", {{"spacing", 0.0005}}}, {"time", {{"end", 100}, {"unit", "s"}, {"snapshots", {50, 100}}}}}, out);
  check_plain_page(out / "report.html", "plate.png", "bond-based peridynamic (PD) mechanics",
                   {"Largest displacement", "Sensor A, 100 s", "Broken bonds"}, 2);
}

TEST_CASE(
    "Headless Chromium shows a frost run's report: the method, the pores' cards, temperature maps, no shaft parts",
    "[shared][browser][frost]") {
  REQUIRE(have_chromium());
  fs::create_directories(artifacts);
  const fs::path out = artifacts / "frost";
  fs::remove_all(out);
  // mortar_frost at 8 µm (1 369 particles), the first 12 ms (five pores start to freeze, bonds break), two snapshots.
  test::run_shipped("mortar_frost.json",
                    {{"numerics", {{"spacing", 8e-6}}}, {"time", {{"end", 0.012}, {"snapshots", {0.006, 0.012}}}}},
                    out);
  check_plain_page(
      out / "report.html", "frost.png", "Frost damage of a porous solid",
      {"Pores frozen", "Pores cracked", "Saturation", "Largest displacement", "Broken bonds", "First crack"}, 2);
}
