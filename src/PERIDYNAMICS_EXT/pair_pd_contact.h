/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/contact, short-range contact forces on
   their own short neighbor list.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(pd/contact,PairPDContact);
// clang-format on
#else

#ifndef LMP_PAIR_PD_CONTACT_H
#define LMP_PAIR_PD_CONTACT_H

#include "pair.h"

namespace LAMMPS_NS {

class PairPDContact : public Pair {
 public:
  PairPDContact(class LAMMPS *);
  ~PairPDContact() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  double memory_usage() override;
  // Each atom's contact spring stiffness sum (core/pd_tangent.h), owned and
  // ghost, over the candidates closer than their contact distance plus
  // 'reach' (how much closer a pair may come before the next estimate):
  // fix pd/timestep; and the largest relative closing rate of those pairs
  // (pd_closing_rate). The caller adds the ghosts' share onto their owners.
  void tangent_sum(double *sum, double *closing, double reach) const;

 protected:
  double **stiffness;     // c_s per type pair; NaN: 15 c of the material (MS07)
  double **distance;      // contact distance per type pair; NaN: r_i + r_j from volumes
  double cutmax_contact;  // the list's cutoff (largest contact distance)
  class PairPD *material; // the pd/ material style (c, horizon), if any
  double friction;        // Coulomb friction coefficient (0: none)
  int legacy;             // reproduce peri/pmb's and peri/lps's contact
  int dim;
  double thickness;
  double skin_short;      // skin of the short list (NaN: default; 0: none)
  double skin_used;       // the one of this run
  int report;             // log the list's size at the next build
  // contact candidates of this neighbor list (pairs that were never bond
  // partners, those are the material's business) with their contact
  // distances, taken at reneighboring, and the short list of those that
  // can touch before it is taken again
  class PDContactCache *cache;
  bigint cache_build;     // the neighbor build the candidates were taken from
  double **legacy_c, **legacy_delta;    // legacy: the material's c and horizon per type pair

  void allocate();
  void filter_pairs();
  void report_stable_dt();
};

}    // namespace LAMMPS_NS

#endif
#endif
