// The frostwall command. Exit status: 0 done, 2 bad input (nothing
// written), 1 failure during a run.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <omp.h>
#include <unistd.h>

#include "calibrate/run_calibrate.hpp"
#include "project/project.hpp"
#include "report/report.hpp"
#include "run/check_project.hpp"
#include "run/run_project.hpp"
#include "study/run_layers.hpp"
#include "study/run_intact.hpp"
#include "study/run_sections.hpp"
#include "study/study_report.hpp"

namespace {

// Under mpirun every rank runs the command; rank 0 writes the files.
bool first_rank() {
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  return !rank || std::string(rank) == "0";
}

// Progress goes to a terminal only: quiet in CI and when piped.
bool show_progress() { return isatty(fileno(stderr)) && std::getenv("CI") == nullptr; }

std::function<void(double, double)> progress_printer(const frostwall::project::TimeSettings& time) {
  if (!show_progress()) return {};
  const double unit = time.unit_seconds();
  const char* unit_name =
      time.unit == frostwall::project::TimeUnit::d ? "d" : (time.unit == frostwall::project::TimeUnit::h ? "h" : "s");
  auto start = std::chrono::steady_clock::now();
  auto last = start;
  return [=](double t, double t_end) mutable {
    const auto now = std::chrono::steady_clock::now();
    if (now - last < std::chrono::milliseconds(200) && t < t_end) return;
    last = now;
    const double wall = std::chrono::duration<double>(now - start).count();
    fmt::print(stderr, "\r  {:.3g} / {:.3g} {} simulated ({:3.0f} %), {:.3g} {}/s  ", t / unit, t_end / unit, unit_name,
               100.0 * t / t_end, wall > 0 ? t / unit / wall : 0.0, unit_name);
    if (t >= t_end) fmt::print(stderr, "\n");
  };
}

// The project file loaded, its warnings printed; nullopt after printing
// its problems (bad input).
std::optional<frostwall::project::Project> load_or_report(const std::string& file) {
  try {
    auto p = frostwall::project::load_project(file);
    for (const auto& w : p.warnings) std::cerr << "warning: " << w << "\n";
    return p;
  } catch (const frostwall::project::ProjectError& e) {
    for (const auto& line : e.problems()) std::cerr << line << "\n";
    return std::nullopt;
  }
}

std::string text_of(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A command's work: bad input ends it with its lines and status 2, any other
// failure with one line and status 1 ("frostwall: <verb> failed: ...").
template <class Work>
int exit_status(const char* verb, Work&& work) {
  try {
    work();
  } catch (const frostwall::project::ProjectError& e) {
    for (const auto& line : e.problems()) std::cerr << line << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "frostwall: " << verb << " failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

int run_command(const std::string& file, int jobs, int threads) {
  using namespace frostwall;
  const auto loaded = load_or_report(file);
  if (!loaded) return 2;
  const project::Project& p = *loaded;
  run::RunOptions options;
  options.project_text = text_of(file);  // the text as given, recorded beside the results (project.json)
  options.progress = progress_printer(p.time);
  options.note = [](const std::string& s) { std::cerr << s << "\n"; };
  const int status = exit_status("run", [&] {
    if (p.survey) {
      // The shaft as built: one full-ring section per depth, side by side
      // (and over the ranks under mpirun).
      study::StudyOptions sections;
      sections.note = options.note;
      sections.jobs = jobs;
      sections.threads = threads;
      study::run_sections(p, options.project_text, sections);
    } else if (p.compare_intact) {
      // The failed-pipe scenario beside the intact layout.
      study::StudyOptions pair;
      pair.note = options.note;
      pair.jobs = jobs;
      pair.threads = threads;
      study::run_with_intact(p, options.project_text, pair);
    } else if (!p.layers.empty()) {
      // One cross-section per layer, side by side as a study runs its variants.
      study::StudyOptions layered;
      layered.note = options.note;
      layered.jobs = jobs;
      layered.threads = threads;
      std::cerr << "layers: " << p.layers.size() << " cross-sections into " << p.output.directory << "\n";
      study::run_layers(p, options.project_text, layered);
    } else {
      run::run_project(p, options);
      // The report, from the files the run just wrote (one rank writes them).
      if (p.output.report && first_rank()) report::write_report(p.output.directory);
    }
  });
  if (status != 0) return status;
  // Under mpirun every rank runs this; one says so.
  if (first_rank()) std::cerr << "wrote " << p.output.directory << "\n";
  return 0;
}

// Checks a project as `run` does before any work, and prints what the run
// would be; writes nothing. Exit status as `run`'s on bad input.
int check_command(const std::string& file) {
  using namespace frostwall;
  const auto p = load_or_report(file);
  if (!p) return 2;
  return exit_status("check", [&] {
    const auto lines = p->survey           ? study::check_sections(*p, text_of(file))
                       : p->layers.empty() ? run::check_project(*p)
                                           : study::check_layers(*p, text_of(file));
    std::cout << file << ": can run (output into " << p->output.directory << ")\n";
    for (const auto& line : lines) std::cout << "  " << line << "\n";
    if (p->plant) {
      const std::size_t sections = p->survey           ? study::section_runs(*p, text_of(file)).size()
                                   : p->layers.empty() ? 1
                                                       : p->layers.size();
      std::cout << "  " << run::describe_plant(*p, sections) << "\n";
    }
    if (p->calibration) {
      calibrate::check_calibration(*p);
      std::cout << "  " << calibrate::describe_calibration(*p) << "\n";
    }
  });
}

// Rebuilds report.html from the files of an output directory.
int report_command(const std::string& dir) {
  if (!std::filesystem::is_regular_file(std::filesystem::path(dir) / "summary.json")) {
    std::cerr << dir << ": no summary.json here; give the output directory of a frostwall run\n";
    return 2;
  }
  return exit_status("report", [&] { std::cerr << "wrote " << frostwall::report::write_report(dir).string() << "\n"; });
}

// Fits the ground's parameters to the thermometers, runs the project as
// calibrated and writes its report with the calibration section.
int calibrate_command(const std::string& file, int jobs, int threads) {
  using namespace frostwall;
  const auto loaded = load_or_report(file);
  if (!loaded) return 2;
  const project::Project& p = *loaded;
  calibrate::CalibrateOptions options;
  options.project_text = text_of(file);
  options.jobs = jobs;
  options.threads = threads;
  options.note = [](const std::string& s) { std::cerr << s << "\n"; };
  options.progress = progress_printer(p.time);
  const int status = exit_status("calibrate", [&] {
    calibrate::run_calibration(p, options);
    if (p.output.report) report::write_report(p.output.directory);
  });
  if (status == 0) std::cerr << "wrote " << p.output.directory << "\n";
  return status;
}

// Runs every variant of a study file, then writes study.html and study.csv.
int study_command(const std::string& file, int jobs, int threads) {
  using namespace frostwall;
  study::Study s;
  try {
    s = study::load_study(file);
  } catch (const study::StudyError& e) {
    for (const auto& line : e.problems()) std::cerr << line << "\n";
    return 2;
  }
  study::StudyOptions options;
  options.jobs = jobs;
  options.threads = threads;
  options.note = [](const std::string& line) { std::cerr << line << "\n"; };
  std::cerr << "study: " << s.variants.size() << " variants into " << s.output_directory.string() << "\n";
  study::StudyRun run;
  try {
    run = study::run_and_write_study(s, options);
  } catch (const std::exception& e) {
    std::cerr << "frostwall: study failed: " << e.what() << "\n";
    return 1;
  }
  const auto failed = std::count_if(run.variants.begin(), run.variants.end(), [](const auto& v) { return !v.ok; });
  std::cerr << fmt::format("wrote {} ({} variants, {} failed, {:.1f} s)\n",
                           (s.output_directory / "study.html").string(), run.variants.size(), failed, run.seconds);
  return failed > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"frostwall: ground that freezes, cracks and washes away (freezing, PD mechanics and CFD-DEM engines)"};
  app.require_subcommand(1);
  auto* run = app.add_subcommand("run", "run a project file and write its results");
  std::string project_file;
  int threads = 0;
  run->add_option("project", project_file, "project file (JSON)")->required();
  int run_jobs = 0;
  run->add_option("--jobs", run_jobs,
                  "layers or as-built sections at once, each on --threads threads (default: one per core, 1 thread "
                  "each)");
  auto* check = app.add_subcommand(
      "check", "check a project file without running it; print the particles, steps and an estimated run time");
  std::string check_file;
  check->add_option("project", check_file, "project file (JSON)")->required();
  auto* report = app.add_subcommand("report", "rebuild report.html from the files of an output directory");
  std::string report_dir;
  report->add_option("output-dir", report_dir, "output directory of a run")->required();
  auto* study = app.add_subcommand("study", "run the variants of a study file; write study.html and study.csv");
  std::string study_file;
  int jobs = 0;
  study->add_option("study", study_file, "study file (JSON)")->required();
  study->add_option("--jobs", jobs,
                    "variants at once, each on --threads threads (default: one per core, 1 thread each)");
  auto* calibrate = app.add_subcommand(
      "calibrate", "fit the ground's parameters to thermometer readings; forecast closure with a band");
  std::string calibrate_file;
  int calibrate_jobs = 0;
  calibrate->add_option("project", calibrate_file, "project file (JSON) with \"calibrate\"")->required();
  calibrate->add_option("--jobs", calibrate_jobs,
                        "forward runs at once (default: one per core, the cores shared among them)");
  app.add_option("--threads", threads, "OpenMP threads (default: all cores; in a study: per variant)");
  app.set_version_flag("--version", FROSTWALL_VERSION);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (threads > 0) omp_set_num_threads(threads);
  if (run->parsed()) return run_command(project_file, run_jobs, threads);
  if (check->parsed()) return check_command(check_file);
  if (report->parsed()) return report_command(report_dir);
  if (study->parsed()) return study_command(study_file, jobs, threads);
  if (calibrate->parsed()) return calibrate_command(calibrate_file, calibrate_jobs, threads);
  return 2;
}
