// Which grains the cavity has taken in. A grain is lost to the cavity once
// its centre has entered the cavity's original sphere, whether it then
// stays there (the default: the void keeps what falls into it) or is
// deleted (cavity.drain: a leak carries it away). Each rank marks the
// grains it holds after every chunk of DEM steps; count() joins the marks
// of all ranks (a grain may have moved between ranks since).
#pragma once

#include <vector>

#include "dem/lammps_session.hpp"
#include "project/cfd_dem.hpp"

namespace frostwall::cfd_dem {

class CavityWatch {
 public:
  CavityWatch(const project::CfdDem& c, const dem::LammpsSession& lammps);
  // Marks this rank's grains whose centre lies in the cavity now.
  void observe();
  // Collective: the grains ever marked, on all ranks; every rank then holds the union.
  double count();
  // 1 for a grain (by id) marked on this rank or joined by the last count().
  double entered(int id) const;
  // The cavity's sphere holds a centre at x.
  bool inside(const double* x) const;
  // How many grains of the mean size the void holds at random close
  // packing (solid fraction 0.64): the most that can fall in and stay.
  double capacity() const;

 private:
  const project::CfdDem& c_;
  const dem::LammpsSession& lammps_;
  std::vector<unsigned char> marked_;  // by grain id
};

}  // namespace frostwall::cfd_dem
