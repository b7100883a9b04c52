// Where the sources, the program and the test artifacts are, as configured
// by CMake (tests/paths.cpp.in). Only the generated tests/paths.cpp carries
// these absolute paths, so every other test file compiles the same in any
// clone and a compiler cache shares it between clones.
#pragma once

namespace frostwall::test {

const char* source_dir();    // the repository root
const char* program();       // the frostwall program
const char* artifact_dir();  // build/test-artifacts

}  // namespace frostwall::test

#define FROSTWALL_SOURCE_DIR (::frostwall::test::source_dir())
#define FROSTWALL_EXE (::frostwall::test::program())
#define FROSTWALL_ARTIFACT_DIR (::frostwall::test::artifact_dir())
