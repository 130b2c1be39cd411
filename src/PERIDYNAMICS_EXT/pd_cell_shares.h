/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: the shares of partner cells inside the horizon
   (core/pd_quadrature.h) for the family build, remembered per distinct
   bond shape.

   A 3D share costs a few microseconds; a lattice has only a few hundred
   distinct bond shapes but millions of bonds. Bonds are keyed by their
   components' magnitudes, sorted (the share is the same for mirror images
   and permutations), rounded to 2^-40 of the horizon, and the cell side
   and horizon bits; the share is computed from the rounded key, so it
   depends on the key only (not on which bond or rank saw it first): the
   same shares on any rank count. Rounding moves a cell by at most 1e-12 of
   the horizon. An irregular arrangement has as many shapes as bonds: the
   memory is then dropped every MAX_SHAPES entries.
------------------------------------------------------------------------- */

#ifndef LMP_PD_CELL_SHARES_H
#define LMP_PD_CELL_SHARES_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>

extern "C" {
#include "pd_quadrature.h"
}

namespace LAMMPS_NS {

class PDCellShares {
 public:
  explicit PDCellShares(int dim) : dim(dim) {}

  // the share of the cell of side a centred at xi inside the horizon delta
  double operator()(const double xi[3], double a, double delta)
  {
    static constexpr double SCALE = 1099511627776.0;    // 2^40
    double m[3] = {std::fabs(xi[0]), std::fabs(xi[1]), dim == 3 ? std::fabs(xi[2]) : 0.0};
    std::sort(m, m + dim);
    Key key{};
    for (int k = 0; k < dim; k++) key[k] = (int64_t) std::llround(m[k] / delta * SCALE);
    std::memcpy(&key[3], &a, sizeof a);
    std::memcpy(&key[4], &delta, sizeof delta);
    auto found = shares.find(key);
    if (found != shares.end()) return found->second;
    double c[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < dim; k++) c[k] = (double) key[k] / SCALE * delta;
    const double f = pd_cell_fraction(dim, c, a, delta);
    if (shares.size() >= MAX_SHAPES) shares.clear();
    shares.emplace(key, f);
    return f;
  }

 private:
  static constexpr size_t MAX_SHAPES = 200000;
  using Key = std::array<int64_t, 5>;
  int dim;
  std::map<Key, double> shares;
};

}    // namespace LAMMPS_NS

#endif
