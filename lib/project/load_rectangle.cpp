// Reads a rectangle's geometry (project/load_rectangle.hpp).
#include "project/load_rectangle.hpp"

#include <string>
#include <tuple>

#include "project/load_basics.hpp"
#include "project/load_pores.hpp"

namespace frostwall::project::detail {

// A boundary is "adiabatic", {"temperature": T}, {"temperature": T,
// "head": h} or {"head": h} (adiabatic, water flows through it).
SideCondition read_side(const Node& n, std::optional<double>& head) {
  if (!n.given()) return Adiabatic{};
  const std::string forms = R"("adiabatic", {"temperature": T} or {"head": h})";
  if (n.json().is_string()) {
    const auto name = n.json().get<std::string>();
    if (name != "adiabatic") n.problem("unknown boundary condition '" + name + "' (expected " + forms + ")");
    return Adiabatic{};
  }
  if (!n.json().is_object()) {
    n.problem("must be " + forms + ", got " + n.type());
    return Adiabatic{};
  }
  n.object({"temperature", "head"});
  if (n["head"].present()) head = n["head"].number();
  if (!n["temperature"].present() && n["head"].present()) return Adiabatic{};
  return FixedTemperature{read_schedule(n["temperature"].required())};
}

Rectangle read_rectangle(const Node& n) {
  Rectangle rectangle;
  if (!n.object({"type", "width", "height", "boundaries", "pores", "saturation"})) return rectangle;
  n["type"].required().choice<int>("geometry type", {{"rectangle", 0}});
  rectangle.width = n["width"].required().positive().value_or(0.0);
  rectangle.height = n["height"].required().positive().value_or(0.0);
  detail::read_pores(n["pores"], rectangle, n["saturation"]);
  const Node sides = n["boundaries"].required();
  if (!sides.object({"left", "right", "top", "bottom"})) return rectangle;
  auto& h = rectangle.heads;
  for (const auto& [key, side, head] :
       {std::tuple{"left", &rectangle.left, &h[0]}, std::tuple{"right", &rectangle.right, &h[1]},
        std::tuple{"top", &rectangle.top, &h[3]}, std::tuple{"bottom", &rectangle.bottom, &h[2]}})
    *side = read_side(sides[key].required(), *head);
  return rectangle;
}

}  // namespace frostwall::project::detail
