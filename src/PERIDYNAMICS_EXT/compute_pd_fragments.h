/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/fragments, the connected components of the
   graph of intact bonds.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(pd/fragments,ComputePDFragments);
// clang-format on
#else

#ifndef LMP_COMPUTE_PD_FRAGMENTS_H
#define LMP_COMPUTE_PD_FRAGMENTS_H

#include "compute.h"

#include <cstdint>
#include <vector>

extern "C" {
#include "pd_fragments.h"
}

namespace LAMMPS_NS {

class ComputePDFragments : public Compute {
 public:
  ComputePDFragments(class LAMMPS *, int, char **);
  ~ComputePDFragments() override;
  void init() override;
  void compute_vector() override;
  void compute_array() override;
  void compute_peratom() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  class FixPDBonds *bonds;
  int64_t min_atoms;      // a fragment of fewer atoms is debris (not counted)
  int nbins;              // rows of the mass distribution
  bool auto_range;        // bins from the lightest particle to the group's mass
  double range_lo, range_hi;

  int nmax;
  int *root;              // union-find forest over owned + ghost atoms, then its roots
  int *slot;              // scratch of pd_fragments_pieces
  int64_t *label;         // smallest atom ID of the fragment (0: not in the group)
  double *fragment_id;    // the per-atom output
  double *mass;           // each owned atom's mass (density x volume)
  int reverse_lowered;    // a ghost's label lowered its owner's (unpack_reverse_comm)
  std::vector<pd_fragment> pieces, fragments;
  bigint labels_step, totals_step;

  void parse(int narg, char **arg);
  void grow();
  bool reusable(int what, bigint step) const;
  void find_labels();
  void find_totals();
  void gather_fragments();
};

}    // namespace LAMMPS_NS

#endif
#endif
