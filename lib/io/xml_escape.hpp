// Text written into XML or HTML by hand (VTK collections, inline SVG): the
// characters that would end a tag, an attribute or an entity, as entities.
#pragma once

#include <string>
#include <string_view>

namespace frostwall::io {

// &, <, >, " and ' as entities (' as &#39;, which XML and HTML both read).
std::string xml_escape(std::string_view text);

}  // namespace frostwall::io
