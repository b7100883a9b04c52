#include "io/paraview_script.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace frostwall::io {

namespace {

// The fixed part of the script: what it does with the settings above it.
constexpr const char* body = R"PY(
import sys
from paraview.simple import *

paraview.simple._DisableFirstRenderCameraReset()
view = GetActiveViewOrCreate('RenderView')


def line(source, colour, width):
    display = Show(source, view)
    display.ColorArrayName = ['POINTS', '']  # a solid colour (also for an empty contour)
    display.AmbientColor = colour
    display.DiffuseColor = colour
    display.LineWidth = width
    return display


def temperature(reader, visible):
    display = Show(reader, view)
    display.SetRepresentationType('Surface')
    ColorBy(display, ('POINTS', 'temperature'))
    lut = GetColorTransferFunction('temperature')
    lut.ApplyPreset('Cool to Warm', True)
    # White at the freezing point when the temperatures cross it; else at
    # their middle (a solid that does not freeze).
    centre = FREEZING_POINT if COLDEST <= FREEZING_POINT <= WARMEST else 0.5 * (COLDEST + WARMEST)
    half = max(centre - COLDEST, WARMEST - centre, 1e-3)
    lut.RescaleTransferFunction(centre - half, centre + half)
    lut.AutomaticRescaleRangeMode = 'Never'
    if visible:
        display.SetScalarBarVisibility(view, True)
    shown = [display]
    front = Contour(registrationName='frozen front', Input=reader)
    front.ContourBy = ['POINTS', 'liquid_fraction']
    front.Isosurfaces = [0.5]
    shown.append(line(front, [0.0, 0.0, 0.0], 2.0))
    if ISOTHERM is not None:
        iso = Contour(registrationName='design isotherm', Input=reader)
        iso.ContourBy = ['POINTS', 'temperature']
        iso.Isosurfaces = [ISOTHERM]
        shown.append(line(iso, [1.0, 0.0, 1.0], 3.0))
    if SOLID:
        warped = WarpByVector(registrationName='displaced', Input=reader)
        warped.Vectors = ['POINTS', 'displacement']
        damage = Show(warped, view)
        ColorBy(damage, ('POINTS', 'damage'))
        Hide(warped, view)
    return shown


def grains(reader, visible):
    display = Show(reader, view)
    display.SetRepresentationType('Point Gaussian')
    display.ShaderPreset = 'Sphere'
    display.ScaleByArray = 1
    display.SetScaleArray = ['POINTS', 'radius']
    display.UseScaleFunction = 0
    display.GaussianRadius = 1.0
    ColorBy(display, ('POINTS', 'displacement', 'Magnitude'))
    GetColorTransferFunction('displacement').ApplyPreset('Viridis (matplotlib)', True)
    if visible:
        display.SetScalarBarVisibility(view, True)
    return [display]


def fluid(reader, visible):
    display = Show(reader, view)
    display.SetRepresentationType('Outline')
    ColorBy(display, ('CELLS', 'porosity'))
    return [display]


opened = 0
for name, kind, visible in SERIES:
    path = os.path.join(HERE, name)
    if not os.path.exists(path):
        continue
    opened += 1
    # A time series (.pvd), or the shaft in 3-D (shaft.vtm: sections at their depths, pipe traces).
    reader = PVDReader(registrationName=name, FileName=path) if name.endswith('.pvd') else OpenDataFile(path)
    displays = {'temperature': temperature, 'grains': grains, 'fluid': fluid}[kind](reader, visible)
    if not visible:
        for display in displays:
            display.Visibility = 0

if not opened:
    print('open_in_paraview.py: none of %s in %s; set HERE to the run\'s folder' % ([s[0] for s in SERIES], HERE))
GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
GetAnimationScene().AnimationTime = GetTimeKeeper().TimestepValues[-1] if GetTimeKeeper().TimestepValues else 0.0
if any(kind in ('grains', 'fluid') for _, kind, _ in SERIES):
    # Grains settle along -z: look at the box from the side.
    view.CameraPosition = [0.0, -1.0, 0.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
elif any(name.endswith('.vtm') for name, _, _ in SERIES):
    # The shaft in 3-D: look down at it from the side and above.
    view.CameraPosition = [1.0, -1.6, 0.8]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
else:
    view.InteractionMode = '2D'
view.ResetCamera()
Render()
if '--png' in getattr(sys, 'argv', []):
    SaveScreenshot(os.path.join(HERE, 'open_in_paraview.png'), view, ImageResolution=[1200, 900])
)PY";

const char* kind_name(ParaviewSeries::Kind k) {
  switch (k) {
    case ParaviewSeries::Kind::temperature: return "temperature";
    case ParaviewSeries::Kind::grains: return "grains";
    case ParaviewSeries::Kind::fluid: return "fluid";
  }
  return "temperature";
}

}  // namespace

void write_paraview_script(const std::filesystem::path& file, const ParaviewScene& scene) {
  if (scene.series.empty()) throw std::invalid_argument("write_paraview_script: no series");
  // JSON strings are Python string literals (the same escapes).
  auto quoted = [](const std::string& s) { return nlohmann::json(s).dump(); };
  std::string series;
  for (const auto& s : scene.series)
    series += fmt::format("    ({}, '{}', {}),\n", quoted(s.pvd), kind_name(s.kind), s.visible ? "True" : "False");
  const std::string head =
      fmt::format("# Opens the files of the frostwall run {} in ParaView with its colour maps:\n"
                  "#   paraview --script=open_in_paraview.py      (the ParaView window)\n"
                  "#   pvpython open_in_paraview.py --png         (no window: saves open_in_paraview.png)\n"
                  "# Temperature diverges at the freezing point; black lines: the frozen front\n"
                  "# (liquid fraction 0.5); magenta: the design isotherm; grains: spheres of\n"
                  "# their radius coloured by displacement. Edit the settings below freely.\n"
                  "import os\n"
                  "HERE = os.path.dirname(os.path.abspath(__file__)) if '__file__' in globals() else os.getcwd()\n"
                  "FREEZING_POINT = {:.6g}  # degC\n"
                  "COLDEST = {:.6g}  # degC\n"
                  "WARMEST = {:.6g}  # degC\n"
                  "ISOTHERM = {}  # degC, or None\n"
                  "SOLID = {}  # displacement and damage in the temperature files\n"
                  "SERIES = [  # (collection, kind, shown at start)\n{}]\n",
                  quoted(scene.title), scene.freezing_point, scene.coldest, scene.warmest,
                  scene.isotherm ? fmt::format("{:.6g}", *scene.isotherm) : std::string("None"),
                  scene.solid ? "True" : "False", series);
  write_text_file(file, head + body);
}

}  // namespace frostwall::io
