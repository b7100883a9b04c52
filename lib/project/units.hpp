// Units the project's numbers are given and reported in, as factors to SI.
#pragma once

namespace frostwall::project {

inline constexpr double seconds_per_day = 86400.0;

}  // namespace frostwall::project
