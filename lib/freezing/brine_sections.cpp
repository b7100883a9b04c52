#include "freezing/brine_sections.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "freezing/heat_run.hpp"
#include "freezing/model.hpp"
#include "particles/side_by_side.hpp"

namespace frostwall::freezing {

namespace {

// The hat functions of linear interpolation between sorted depths (held
// beyond the ends), at z.
std::vector<double> hats(const std::vector<double>& depth, double z) {
  std::vector<double> phi(depth.size(), 0.0);
  if (z <= depth.front()) phi.front() = 1.0;
  else if (z >= depth.back()) phi.back() = 1.0;
  else
    for (std::size_t k = 0; k + 1 < depth.size(); ++k)
      if (z >= depth[k] && z <= depth[k + 1]) {
        const double s = (z - depth[k]) / (depth[k + 1] - depth[k]);
        phi[k] = 1.0 - s, phi[k + 1] = s;
        break;
      }
  return phi;
}

// The brine along the pipe at a stop for each profile time reached: the
// profile from a supply at 0 shifted by the supply that ran.
void keep_profiles(const std::vector<double>& times, std::size_t& next, double stop, const design::BrineProfile& base,
                   double supply, double return_temperature, std::vector<PlantProfile>& out) {
  for (; next < times.size() && times[next] <= stop; ++next) {
    if (!out.empty() && out.back().time == stop) continue;
    PlantProfile at{stop, base};
    for (auto* channel : {&at.brine.down, &at.brine.up})
      for (double& T : *channel) T += supply;
    at.brine.supply = supply, at.brine.return_temperature = return_temperature;
    out.push_back(std::move(at));
  }
}

// The next exchange's interval: the shortest while the plant is held at its
// capacity or a section's brine moved by more than `settled` over the last
// one; else twice the last, up to the longest.
double next_interval(const CircuitSettings& s, double last, double supply, const std::vector<double>& before,
                     const std::vector<double>& after) {
  double moved = 0.0;
  for (std::size_t k = 0; k < before.size(); ++k) moved = std::max(moved, std::abs(after[k] - before[k]));
  const bool held_at_capacity = s.capacity && supply > s.min_supply;
  if (held_at_capacity || moved > s.settled) return s.interval;
  return std::min(2.0 * last, std::max(s.interval, s.longest_interval));
}

// One section marched in the circuit.
struct Marching {
  project::RunOptions options;
  Model model;
  std::unique_ptr<SteppedHeatRun> run;
  std::size_t pipe = 0;      // the pipe boundary
  double pipes_in = 1.0;     // whole pipes' worth of wall in the section
  double heat_before = 0.0;  // J per metre of section, through the pipe walls, up to the last stop
};

}  // namespace

CircuitRun run_brine_circuit(const std::vector<CircuitSection>& sections, const CircuitSettings& s,
                             const project::RunOptions& options) {
  if (sections.empty()) throw std::invalid_argument("run_brine_circuit: no section");
  if (!(s.interval > 0.0) || s.cells < 1 || !(s.flow > 0.0) || s.pipes < 1)
    throw std::invalid_argument("run_brine_circuit: interval, cells, flow and pipes must be positive");
  // The brine's films and capacity rate at its properties now.
  design::Brine fluid = s.brine_at ? s.brine_at(s.supply.at(0.0)) : s.brine;
  design::CoaxialResistances r;
  double W = 0.0, film = 0.0, h = 0.0;  // W/K; W/(m K) per metre of pipe; W/(m2 K) on the outer wall
  auto take_brine = [&](const design::Brine& b) {
    fluid = b;
    r = design::coaxial_resistances(s.pipe, fluid, s.flow);
    W = fluid.density * fluid.heat_capacity * s.flow;
    film = 1.0 / r.ground;
    h = film / (M_PI * s.pipe.outer_diameter);
  };
  take_brine(fluid);
  std::vector<double> depth;
  for (const auto& c : sections) depth.push_back(c.depth);
  if (!std::is_sorted(depth.begin(), depth.end())) throw std::invalid_argument("run_brine_circuit: depths not sorted");

  CircuitRun out;
  // Each section's weight: its hat function on the cells' midpoints, as the
  // brine's march samples the draw.
  out.weights.assign(sections.size(), 0.0);
  const double cell = s.pipe.length / s.cells;
  for (int c = 0; c < s.cells; ++c) {
    const auto phi = hats(depth, (c + 0.5) * cell);
    for (std::size_t k = 0; k < phi.size(); ++k) out.weights[k] += cell * phi[k];
  }

  std::vector<project::Project> projects;
  for (const auto& c : sections) {
    auto p = c.project;
    auto& pipe = std::get<project::ShaftSection>(p.geometry).pipe;
    pipe.boundary = project::PipeBoundary::brine;
    pipe.heat_transfer_coefficient = h;
    pipe.annulus.reset();
    pipe.temperature = project::TemperatureSchedule::fixed(s.supply.at(0.0));  // set again before the first step
    projects.push_back(std::move(p));
  }
  std::vector<Marching> runs(sections.size());
  for (std::size_t k = 0; k < sections.size(); ++k) {
    auto& m = runs[k];
    m.model = build_model(projects[k]);
    m.pipe = static_cast<std::size_t>(m.model.shaft->pipe_boundary);
    const auto& film = *m.model.model->boundaries()[m.pipe].film;
    m.pipes_in = 0.0;
    for (double l : film.perimeter) m.pipes_in += l / film.full_perimeter;
    m.options = options;
    if (!sections[k].project_text.empty()) m.options.project_text = sections[k].project_text;
    m.run = std::make_unique<SteppedHeatRun>(projects[k], m.model, m.options, sections[k].extension);
  }

  const double end = projects.front().time.end;
  const int cores = particles::usable_cores();
  const int jobs = std::min<int>(cores, static_cast<int>(runs.size())), threads = std::max(1, cores / jobs);
  // Each section's brine, and its wall's mean temperature over the last
  // interval (at the start, the ground's).
  std::vector<double> brine(runs.size()), wall(runs.size());
  for (std::size_t k = 0; k < runs.size(); ++k) wall[k] = projects[k].domain.initial_temperature;
  std::vector<double> draw(runs.size(), 0.0), warming(runs.size(), 0.0);  // W/m; K above the supply
  double t = 0.0;
  auto set_brine = [&](double supply, double at) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      brine[k] = supply + warming[k];
      runs[k].model.model->set_boundary_temperature(runs[k].pipe, project::TemperatureSchedule::fixed(brine[k]));
      runs[k].model.model->set_film_coefficient(runs[k].pipe, h);
      runs[k].model.model->apply_boundaries(at);
    }
  };
  // The supply for the coming interval: scheduled, or the one drawing P.
  auto next_supply = [&](double at) {
    if (!s.capacity) return s.supply.at(at);
    double weight = 0.0, sum = 0.0;
    for (std::size_t k = 0; k < runs.size(); ++k)
      weight += out.weights[k], sum += out.weights[k] * (wall[k] - warming[k]);
    return std::max(s.min_supply, (sum - *s.capacity / (s.pipes * film)) / weight);
  };
  double supply = next_supply(0.0), return_temperature = supply;
  set_brine(supply, 0.0);
  std::size_t next_profile = 0;
  double interval = s.interval;
  while (t < end) {
    const double stop = std::min(end, t + interval);
    // The sections to the stop side by side, the machine's cores shared among them.
    particles::side_by_side(runs.size(), jobs, threads, [&](std::size_t k) { runs[k].run->advance_to(stop); });
    for (std::size_t k = 0; k < runs.size(); ++k) {
      auto& m = runs[k];
      const double heat = m.run->loop().boundary_heat[m.pipe];        // J per metre entered through the walls
      draw[k] = -(heat - m.heat_before) / ((stop - t) * m.pipes_in);  // W per metre of one pipe
      wall[k] = brine[k] + draw[k] / film;                            // the wall's mean over the interval
      out.ground_heat += -(heat - m.heat_before) / m.pipes_in * out.weights[k] * s.pipes;
      m.heat_before = heat;
    }
    const double h_ran = h;
    if (s.brine_at) take_brine(s.brine_at(0.5 * (supply + return_temperature)));
    // The brine's warming to each section's depth at these draws (the same
    // at any supply: the circuit is linear), from a supply at 0.
    const auto base = design::brine_with_draw(s.pipe.length, s.cells, r, W, s.channel, 0.0, [&](double z) {
      const auto phi = hats(depth, z);
      double q = 0.0;
      for (std::size_t k = 0; k < phi.size(); ++k) q += phi[k] * draw[k];
      return q;
    });
    const auto& annulus = base.annulus(s.channel);
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const double x = std::clamp(depth[k] / cell, 0.0, double(s.cells));
      const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), s.cells - 1);
      warming[k] = annulus[i] + (x - i) * (annulus[i + 1] - annulus[i]);
    }
    // The row tells the interval just run: its supply, return and brine.
    return_temperature = supply + base.return_temperature;
    PlantRow row{stop, s.pipes * base.heat, supply, return_temperature, brine, draw, h_ran};
    supply = next_supply(stop);
    set_brine(supply, stop);
    interval = next_interval(s, interval, supply, row.brine, brine);
    keep_profiles(s.profile_times, next_profile, stop, base, row.supply, return_temperature, out.profiles);
    out.plant_heat += row.load * (stop - t);
    out.series.push_back(std::move(row));
    t = stop;
  }
  for (auto& m : runs) out.sections.push_back(m.run->finish());
  out.resistances = r;
  out.brine = fluid;
  return out;
}

}  // namespace frostwall::freezing
