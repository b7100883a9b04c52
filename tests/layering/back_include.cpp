// A deliberate back-include: geometry, a shared room, reaching up to the
// report. Compiled with geometry's include directories (tests/CMakeLists.txt,
// test "layering: a back-include fails to build"), it must not compile.
#include "geometry/layout.hpp"
#include "report/report.hpp"
