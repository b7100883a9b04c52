#include "freezing/shaft_results.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <fmt/core.h>
#include <numbers>

#include "particles/mirror_images.hpp"
#include "io/atomic_file.hpp"
#include "io/polyline_vtk.hpp"
#include "post/closure.hpp"
#include "post/flow_side.hpp"
#include "post/isoline.hpp"
#include "project/units.hpp"
#include "freezing/design_check.hpp"
#include "sph/laplacian.hpp"
#include "freezing/output_frames.hpp"
#include "particles/symmetry_group.hpp"
#include "design/wall_strength.hpp"
#include "summary/summary.hpp"

namespace frostwall::freezing {

namespace keys = summary::keys;

namespace {
using nlohmann::json;

json stretch_json(const post::FrozenStretch& s) {
  return {{keys::inner, summary::number_or_null(s.inner)},
          {keys::outer, summary::number_or_null(s.outer)},
          {keys::thickness, s.thickness}};
}
std::string csv_number(const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : ""; }
}  // namespace

ShaftResults::ShaftResults(const project::Project& p, const Model& m)
    : project_(p),
      model_(m),
      planes_(interface_planes(m.shaft->pipes)),
      sampler_(m.particles(), *m.kernel, m.smoothing) {
  const auto& shaft = *m.shaft;
  const double dx = m.particles().spacing, R = shaft.far_field_radius;
  // The fan over the simulated wedge finds the weakest ray; a second gauge
  // with just OA and OB gives their extents and OB's mean temperature.
  post::RayFan fan{shaft.wedge.start_angle,
                   shaft.wedge.angle,
                   post::RayFan::rays_needed(shaft.wedge.angle, planes_.ring_radius, dx),
                   0.0,
                   R,
                   0.5 * dx};
  fan_gauge_ = std::make_unique<post::WallGauge>(sampler_, fan, planes_.ring_radii, p.design.isotherm);
  planes_gauge_ = std::make_unique<post::WallGauge>(
      sampler_, post::RayFan{planes_.OA, planes_.OB - planes_.OA, 2, 0.0, R, 0.5 * dx}, planes_.ring_radii);

  // Profiles every 0.05 m along OA and OB (the paper's Fig. 5).
  std::vector<particles::Vec<2>> on_OA, on_OB;
  for (double r = 0.0; r <= R + 1e-9; r += 0.05) {
    profile_radii_.push_back(r);
    on_OA.emplace_back(r * std::cos(planes_.OA), r * std::sin(planes_.OA));
    on_OB.emplace_back(r * std::cos(planes_.OB), r * std::sin(planes_.OB));
  }
  auto in_pipe = [&](const std::vector<particles::Vec<2>>& points) {
    std::vector<char> inside(points.size(), 0);
    if (!project::has_wall(std::get<project::ShaftSection>(p.geometry).pipe.model)) return inside;
    for (std::size_t k = 0; k < points.size(); ++k)
      for (const auto& q : shaft.pipes)
        inside[k] |= (points[k] - particles::Vec<2>(q.x, q.y)).norm() < shaft.pipe_radius;
    return inside;
  };
  in_pipe_OA_ = in_pipe(on_OA);
  in_pipe_OB_ = in_pipe(on_OB);
  profile_OA_ = std::make_unique<post::PointProbe>(sampler_, on_OA, true);
  profile_OB_ = std::make_unique<post::PointProbe>(sampler_, on_OB, true);

  sensor_readings_.resize(p.monitoring.size());

  // Front curves: wedge particles with their images; the full ring as copies.
  const auto& P = m.particles();
  curve_points_ = P.position;
  for (std::uint32_t i = 0; i < P.size(); ++i) curve_source_.push_back(i);
  const auto images = particles::mirror_images(P, 3.0 * P.coarsest_spacing(), post::image_reach(P));
  curve_points_.insert(curve_points_.end(), images.position.begin(), images.position.end());
  curve_source_.insert(curve_source_.end(), images.source.begin(), images.source.end());
  if (p.output.full_ring && !P.mirrors.empty())
    for (const auto& g : particles::symmetry_group(P.mirrors, shaft.far_field_radius))
      for (std::uint32_t i = 0; i < P.size(); ++i)
        if (shown_in_files(P, i, std::nullopt)) {
          ring_points_.push_back(g(P.position[i]));
          ring_source_.push_back(i);
        }
}

ShaftResults::~ShaftResults() = default;

ShaftResults::Reading ShaftResults::read(double t, const std::vector<double>& liquid_fraction,
                                         const std::vector<double>& temperature) const {
  std::vector<double> ground;
  if (excavation_) excavation_->as_ground(ground = liquid_fraction);
  const auto& f = excavation_ ? ground : liquid_fraction;
  const auto fan = fan_gauge_->measure(f, temperature);
  const auto planes = planes_gauge_->measure(f, temperature);
  Reading r{t / project::seconds_per_day,
            planes.extents.OA(),
            planes.extents.OB(),
            fan.extents.min_thickness,
            planes.mean_temperature_OB,
            fan.mean_temperature_thinnest,
            {},
            {},
            {},
            {},
            0.0};
  const double weakest = post::weakest_angle(fan_gauge_->fan(), fan.extents) * 180.0 / std::numbers::pi;
  r.weakest_angle_deg = weakest - 360.0 * std::floor(weakest / 360.0);
  if (project_.design.isotherm) {
    r.isotherm_thickness = fan.isotherm.min_thickness;
    r.isotherm_mean_temperature = fan.isotherm_mean_temperature;
  }
  if (project_.groundwater && project_.groundwater->speed() > 0.0) {
    for (int k = 0; k < int(fan.extents.rays.size()); ++k) {
      const double angle = fan_gauge_->fan().ray_angle(k), thick = fan.extents.rays[k].thickness;
      const auto side = post::flow_side({std::cos(angle), std::sin(angle)}, project_.groundwater->darcy_flux);
      if (side == post::FlowSide::flank) continue;
      auto& thinnest = side == post::FlowSide::upstream ? r.upstream_thickness : r.downstream_thickness;
      thinnest = thinnest ? std::min(*thinnest, thick) : thick;
    }
  }
  return r;
}

void ShaftResults::sample(double t, const std::vector<double>& liquid_fraction, const std::vector<double>& temperature,
                          const std::vector<double>& sensors) {
  series_.push_back(read(t, liquid_fraction, temperature));
  for (std::size_t s = 0; s < sensors.size(); ++s)
    sensor_readings_[s].emplace_back(t / project::seconds_per_day, sensors[s]);
}

void ShaftResults::snapshot(double t, const thermal::ThermalModel& model, const std::filesystem::path& out,
                            const std::string& stem) {
  snapshots_.push_back(read(t, model.liquid_fraction(), model.temperature()));
  const double pipe_T = std::get<project::ShaftSection>(project_.geometry).pipe.temperature.at(t);
  auto profile = [&](const post::PointProbe& probe, const std::vector<char>& in_pipe) {
    auto T = probe(model.temperature());
    for (std::size_t k = 0; k < T.size(); ++k)
      if (in_pipe[k]) T[k] = pipe_T;
    return T;
  };
  profiles_OA_.push_back(profile(*profile_OA_, in_pipe_OA_));
  profiles_OB_.push_back(profile(*profile_OB_, in_pipe_OB_));

  // The 0.5 liquid-fraction isoline, kept inside the wedge. Triangles
  // longer than three spacings (holes, hull) carry no front; on a graded
  // cloud, three local spacings.
  const auto& P = model_.particles();
  // The triangulations are built at the first snapshot and reused.
  auto mesh_of = [&](const std::vector<particles::Vec<2>>& points, const std::vector<std::uint32_t>& source) {
    if (!P.graded()) return std::make_unique<post::IsolineMesh>(points, 3.0 * P.spacing);
    std::vector<double> limit(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) limit[k] = 3.0 * P.spacing_of(source[k]);
    return std::make_unique<post::IsolineMesh>(points, limit);
  };
  std::vector<double> shown = model.liquid_fraction();
  if (excavation_) excavation_->as_shown(shown);
  auto values = [&](const std::vector<std::uint32_t>& source) {
    std::vector<double> v(source.size());
    for (std::size_t k = 0; k < source.size(); ++k) v[k] = shown[source[k]];
    return v;
  };
  const auto& wedge = model_.shaft->wedge;
  if (!curve_mesh_) curve_mesh_ = mesh_of(curve_points_, curve_source_);
  const auto kept = post::clip_polylines(curve_mesh_->isolines(values(curve_source_), 0.5),
                                         [&](const particles::Vec<2>& x) { return geometry::inside_wedge(wedge, x); });
  const std::string file = "interface" + stem.substr(5) + ".vtp";
  io::write_vtp(out / file, kept, io::file_labels(project_));
  json entry = {{keys::day, t / project::seconds_per_day}, {"file", file}};
  if (!ring_points_.empty()) {
    const std::string ring_file = "interface_ring" + stem.substr(5) + ".vtp";
    if (!ring_mesh_) {
      // The ring files' triangles (output_frames.hpp): three local spacings,
      // none across a pipe disc.
      std::vector<double> limit(ring_source_.size()), boundary(ring_source_.size());
      for (std::size_t k = 0; k < limit.size(); ++k)
        limit[k] = 3.0 * P.spacing_of(ring_source_[k]), boundary[k] = P.boundary[ring_source_[k]];
      ring_mesh_ =
          std::make_unique<post::IsolineMesh>(ring_points_, ground_triangles(ring_points_, limit, boundary, true));
    }
    io::write_vtp(out / ring_file, ring_mesh_->isolines(values(ring_source_), 0.5), io::file_labels(project_));
    entry["full_ring_file"] = ring_file;
  }
  interface_.push_back(entry);
}

// One entry per snapshot; with a strength check, each entry's check, and
// `met` when and whether the wall carries the pressure.
json ShaftResults::wall_entries(std::optional<DesignMet>& met) const {
  // ---- wall: one entry per snapshot
  json wall = json::array();
  for (const auto& r : snapshots_)
    wall.push_back({{keys::day, r.day},
                    {keys::OA, stretch_json(r.OA)},
                    {keys::OB, stretch_json(r.OB)},
                    {keys::min_thickness, r.min_thickness},
                    {keys::thinnest_angle_deg, r.weakest_angle_deg},
                    {keys::mean_temperature_OB, summary::number_or_null(r.mean_temperature_OB)}});
  if (project_.design.isotherm)
    for (std::size_t k = 0; k < snapshots_.size(); ++k) {
      wall[k][keys::isotherm_thickness] = summary::number_or_null(snapshots_[k].isotherm_thickness);
      wall[k][keys::isotherm_mean_temperature] = summary::number_or_null(snapshots_[k].isotherm_mean_temperature);
    }
  if (project_.groundwater && project_.groundwater->speed() > 0.0)
    for (std::size_t k = 0; k < snapshots_.size(); ++k) {
      wall[k][keys::min_thickness_upstream] = summary::number_or_null(snapshots_[k].upstream_thickness);
      wall[k][keys::min_thickness_downstream] = summary::number_or_null(snapshots_[k].downstream_thickness);
    }
  // The wall check from the ground pressure and the frozen soil's strength.
  const auto& design = project_.design;
  if (design.checks_strength()) {
    for (std::size_t k = 0; k < snapshots_.size(); ++k) {
      const auto& r = snapshots_[k];
      const WallCheck c = check(r);
      wall[k]["mean_temperature_thinnest"] = summary::number_or_null(r.mean_temperature_thinnest);
      wall[k]["allowable_strength"] = summary::number_or_null(c.allowable);
      wall[k][keys::required_thickness] = summary::number_or_null(c.required);
      wall[k]["required_by"] = c.required_by;
      wall[k][keys::utilisation] = summary::number_or_null(c.utilisation);
    }
    // The day it is met: on the time series (every output interval), not
    // only at the snapshots.
    std::vector<double> days;
    std::vector<WallCheck> checks;
    for (const auto& r : series_) days.push_back(r.day), checks.push_back(check(r));
    met = design_met(days, checks);
  }

  return wall;
}

WallCheck ShaftResults::check(const Reading& r) const {
  const auto& design = project_.design;
  const double a = std::get<project::ShaftSection>(project_.geometry).shaft.excavation_radius.value_or(0.0);
  // Measured on the design isotherm when there is one, else on the frozen front.
  return design.isotherm ? check_wall(design, a, r.isotherm_thickness.value_or(0.0), r.isotherm_mean_temperature)
                         : check_wall(design, a, r.min_thickness, r.mean_temperature_thinnest);
}

// The first time both targets hold (thickness interpolated) and the
// strength check's verdict; null when the project sets no target.
json ShaftResults::design_entry(const std::optional<DesignMet>& met) const {
  const auto& design = project_.design;
  json result;
  if (design.required_thickness || design.max_mean_temperature || met) {
    auto meets = [&](const Reading& r) {
      const bool thick = !design.required_thickness || r.min_thickness >= *design.required_thickness;
      const bool cold = !design.max_mean_temperature ||
                        (r.mean_temperature_OB && *r.mean_temperature_OB <= *design.max_mean_temperature);
      return thick && cold;
    };
    std::optional<double> reached;
    for (std::size_t k = 0; k < series_.size() && !reached; ++k) {
      if (!meets(series_[k])) continue;
      reached = series_[k].day;
      // Where the thickness is what turned true, interpolate its crossing.
      if (k > 0 && design.required_thickness) {
        const auto& a = series_[k - 1];
        const auto& b = series_[k];
        Reading a_thick = a;
        a_thick.min_thickness = b.min_thickness;
        if (meets(a_thick) && b.min_thickness > a.min_thickness)
          reached = a.day + (*design.required_thickness - a.min_thickness) / (b.min_thickness - a.min_thickness) *
                                (b.day - a.day);
      }
    }
    result = {{keys::required_thickness, summary::number_or_null(design.required_thickness)},
              {keys::max_mean_temperature, summary::number_or_null(design.max_mean_temperature)},
              {keys::reached_day, summary::number_or_null(reached)},
              {keys::pass, reached.has_value()}};
    if (met) {
      if (!design.required_thickness && !design.max_mean_temperature)  // the strength check is the only target
        result[keys::reached_day] = summary::number_or_null(met->day), result[keys::pass] = met->day.has_value();
      result[keys::met_day] = summary::number_or_null(met->day);
      result["stays_met"] = met->stays;
      result["formula"] = std::string(design::name(design.formula));
      result["pressure_MPa"] = *design.pressure;
      result["allowable_factor"] = design.allowable_factor;
      result["depth"] = summary::number_or_null(design.depth);
      result["isotherm"] = summary::number_or_null(design.isotherm);
      result["friction_angle"] = summary::number_or_null(design.friction_angle);
      result["measured_on"] = design.isotherm ? fmt::format("the {:g} degC isotherm", *design.isotherm)
                                              : std::string("the frozen front (liquid fraction 0.5)");
    }
  }

  return result;
}

void ShaftResults::write_tables(const std::filesystem::path& out) const {
  std::string csv = "day,OA_inner_m,OA_outer_m,OA_thickness_m,OB_inner_m,OB_outer_m,OB_thickness_m,min_thickness_m,"
                    "mean_temperature_OB_C\n";
  for (const auto& r : series_)
    csv += fmt::format("{:.6g},{},{},{:.6g},{},{},{:.6g},{:.6g},{}\n", r.day, csv_number(r.OA.inner),
                       csv_number(r.OA.outer), r.OA.thickness, csv_number(r.OB.inner), csv_number(r.OB.outer),
                       r.OB.thickness, r.min_thickness, csv_number(r.mean_temperature_OB));
  io::write_text_file(out / "wall.csv", csv);
  auto profile_csv = [&](const std::vector<std::vector<double>>& profiles) {
    std::string text = "r_m";
    for (const auto& r : snapshots_) text += fmt::format(",T_day_{:g}_C", r.day);
    text += "\n";
    for (std::size_t i = 0; i < profile_radii_.size(); ++i) {
      text += fmt::format("{:.4g}", profile_radii_[i]);
      for (const auto& p : profiles) {
        text += ',';
        text += csv_number(std::isnan(p[i]) ? std::nullopt : std::optional(p[i]));
      }
      text += "\n";
    }
    return text;
  };
  io::write_text_file(out / "profiles_OA.csv", profile_csv(profiles_OA_));
  io::write_text_file(out / "profiles_OB.csv", profile_csv(profiles_OB_));
  std::string sensors = "day";
  for (const auto& s : project_.monitoring) sensors += "," + s.name + "_C";
  sensors += "\n";
  const std::size_t rows = sensor_readings_.empty() ? series_.size() : sensor_readings_.front().size();
  for (std::size_t k = 0; k < rows; ++k) {
    sensors += fmt::format("{:.6g}", series_[k].day);
    for (const auto& s : sensor_readings_) sensors += fmt::format(",{:.6g}", s[k].second);
    sensors += "\n";
  }
  io::write_text_file(out / "monitoring.csv", sensors);
}

json ShaftResults::finish(const std::filesystem::path& out) const {
  json result;
  std::optional<DesignMet> met;
  result[keys::wall] = wall_entries(met);
  if (json design = design_entry(met); !design.is_null()) result[keys::design] = std::move(design);
  // ---- monitoring
  json monitoring = json::object();
  for (std::size_t s = 0; s < project_.monitoring.size(); ++s) {
    json series = json::array();
    for (const auto& [d, T] : sensor_readings_[s]) series.push_back({d, T});
    monitoring[project_.monitoring[s].name] = series;
  }
  result[keys::monitoring] = monitoring;
  result[keys::interface] = interface_;
  result["ob_angle_deg"] = planes_.OB * 180.0 / std::numbers::pi;
  // Where the wall is weakest at the last snapshot: the thinnest ray, or the
  // open gap's middle before closure.
  if (!snapshots_.empty()) result[keys::thinnest_angle_deg] = snapshots_.back().weakest_angle_deg;

  write_tables(out);
  return result;
}

}  // namespace frostwall::freezing
