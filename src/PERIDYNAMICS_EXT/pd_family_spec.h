/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: what the bond store needs to know to build the bond
   families, and nothing else of the material.

   The material pair style (PairPD) describes its families as a value: the
   horizon of every type pair, the quadrature weight of a new bond, a
   fingerprint of everything that decides which bonds exist ('key'), and
   its own name for messages. The store (fix pd/bonds) copies that value at
   the start of every run from whichever pair style now provides one
   (PDFamilySource, found by type, also as a hybrid sub-style), so it
   never holds a pointer into a pair style: after 'pair_style none' or a
   change of pair style it simply finds no source and keeps its families
   as they are.

   This header includes no pair or fix header: the store and the pair
   style both include it, and not each other's.
------------------------------------------------------------------------- */

#ifndef LMP_PD_FAMILY_SPEC_H
#define LMP_PD_FAMILY_SPEC_H

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace LAMMPS_NS {

// A candidate bond as the store sees it in the reference configuration.
struct PDBondGeometry {
  double xi[3];          // reference bond vector x0_j - x0_i (minimum image)
  double r;              // its length
  double vi, vj;         // the two atoms' volumes
  double horizon;        // of the type pair
  double fraction;       // share of the partner's cell inside the horizon (1: point quadrature)
};

struct PDFamilySpec {
  // The quadrature weight of a new bond. It holds copies of what it needs
  // (no pointer to its pair style).
  using Weight = std::function<double(const PDBondGeometry &)>;
  // The share of the partner's cell inside the horizon (partial-volume
  // quadrature); a candidate with none is no bond.
  using Fraction = std::function<double(const PDBondGeometry &)>;

  std::string style;              // the material style's name, for messages
  double key = 0.0;               // fingerprint of the settings that decide the bonds
  int ntypes = 0;
  std::vector<double> horizons;   // (ntypes+1)^2: NaN for a type of another hybrid
                                  // sub-style, 0 for 'nobond'
  double smallest = INFINITY;     // the smallest horizon of a type of this style
  double beyond = 0.0;            // how far past the horizon a bond may reach (partial cells)
  Fraction fraction;              // null: point quadrature (a bond iff r <= horizon)
  Weight weight;                  // used only when the bonds carry weights
  // (ntypes+1)^2: 1 for two types whose bonds only the mixing rules give
  // (no pair_coeff I J line) while one of them fails and the other not:
  // an impactor and its target, glued if they start within a horizon; the
  // store warns when they share bonds (empty: none)
  std::vector<char> unnamed_mixed;

  double horizon(int i, int j) const { return horizons[(size_t) i * (ntypes + 1) + j]; }
  bool is_unnamed_mixed(int i, int j) const
  {
    return !unnamed_mixed.empty() && unnamed_mixed[(size_t) i * (ntypes + 1) + j];
  }
  // the longest reference distance of a bond between the types (0: none)
  double reach(int i, int j) const
  {
    const double h = horizon(i, j);
    return h > 0.0 ? h + beyond : h;
  }
  // Whether a candidate within reach is a bond: within the horizon (point
  // quadrature) or with a share of its cell inside it (partial); fills
  // g.fraction for the weight.
  bool is_bond(PDBondGeometry &g) const
  {
    if (!fraction) {
      g.fraction = 1.0;
      return g.r <= g.horizon;
    }
    g.fraction = g.r <= g.horizon + beyond ? fraction(g) : 0.0;
    return g.fraction > 0.0;
  }
  double bond_weight(const PDBondGeometry &g) const { return weight(g); }
};

// A pair style that stores bonds: the material base class implements it.
// The store looks for it by type among the current pair style and its
// hybrid sub-styles (no list of style names).
class PDFamilySource {
 public:
  // the families this style asks for, as of its last init_style
  virtual PDFamilySpec family_spec() const = 0;
  // per-atom state the style deferred, made exact while the atoms' indices
  // still hold: before they migrate (pre_exchange), and when a run ends
  virtual void catch_up(bool /*run_ends*/) {}
  // the stable time step estimate of the current state (collective), for
  // the blow-up guard
  virtual double current_stable_dt() = 0;

 protected:
  // Never deleted through this base (the style is deleted as a Pair), so no
  // virtual destructor: a virtual one here would be overridden by the
  // style's destructor, whose exception specification follows LAMMPS's
  // (Pointers' destructor is noexcept(false) from 19Nov2024 on, noexcept
  // before), and a noexcept(false) one cannot override a noexcept one.
  ~PDFamilySource() = default;
};

// The source among the current pair style and its hybrid sub-styles, or
// null (pd_family_spec.cpp).
PDFamilySource *pd_family_source(class Force *force);

}    // namespace LAMMPS_NS

#endif
