// LAMMPS as Debian builds it ends the process on a bad command (no C++
// exceptions): the run must still end with status 1 and one line carrying
// LAMMPS' own ERROR line from its log.
#include <catch2/catch.hpp>

#include "dem/lammps_session.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <sys/wait.h>

namespace fs = std::filesystem;

// Hidden, and out of ctest ([child]): run by the test below in a process of
// its own, since LAMMPS ends it.
TEST_CASE("a LAMMPS session given a bad command", "[.][child][lammps_exit]") {
  const char* log = std::getenv("FROSTWALL_TEST_LAMMPS_LOG");
  REQUIRE(log);
  frostwall::dem::LammpsSession lammps(log);
  lammps.command("units si");
  lammps.command("no_such_command 1");
  FAIL("LAMMPS went on after a bad command");
}

TEST_CASE("a LAMMPS error ends the process with status 1 and LAMMPS' own ERROR line", "[cfd_dem][cli]") {
  frostwall::test::TempDir dir;
  const fs::path self = fs::read_symlink("/proc/self/exe");
  const fs::path log = dir.path / "lammps.log";
  const std::string command = "FROSTWALL_TEST_LAMMPS_LOG='" + log.string() + "' timeout 30 '" + self.string() +
                              "' '[lammps_exit]' >'" + (dir.path / "out.txt").string() + "' 2>'" +
                              (dir.path / "err.txt").string() + "'";
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);
  const std::string err = frostwall::test::read_text(dir.path / "err.txt");
  INFO(err);
  const std::string expected_start = "frostwall: run failed: LAMMPS ERROR: Unknown command: no_such_command";
  CHECK(err.starts_with(expected_start));
  CHECK(err.find("(" + log.string() + ")\n") != std::string::npos);
  // One line, and it is the log's own ERROR line.
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  const std::string logged = frostwall::test::read_text(log);
  CHECK(logged.find(err.substr(std::string("frostwall: run failed: LAMMPS ").size(), 40)) != std::string::npos);
}
