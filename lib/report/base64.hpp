// Base64 (RFC 4648) for the images the report carries inline as data URIs.
#pragma once

#include <string>
#include <string_view>

namespace frostwall::report {

std::string base64(std::string_view bytes);

}  // namespace frostwall::report
