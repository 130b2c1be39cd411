/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: the fracture record of the bond store.

   What the bonds' failure has done so far: bonds broken by fracture, the
   energy dissipated in the bonds (fracture, plastic work), whether any
   bond anywhere is broken, and the breaks since the last mapping of the
   partners (which the lost-bond count subtracts). And the fresh-bond
   replay: the bonds that broke at the last force evaluation, so that a
   second evaluation of that step (the setup of the next run, or the first
   evaluation after a restart) applies the same forces as the first.

   The bond store (fix pd/bonds) owns one record and writes it to restart
   files; the material pair styles book into it (pair_pd.cpp), computes
   read it (compute pd/fracture). The record reads and writes the bonds
   only through a PDBondTable, the store's rows as plain arrays.
------------------------------------------------------------------------- */

#ifndef LMP_PD_FRACTURE_RECORD_H
#define LMP_PD_FRACTURE_RECORD_H

#include "lmptype.h"
#include "pointers.h"

#include <cmath>
#include <vector>

namespace LAMMPS_NS {

// The bonds as the store keeps them: one row of 'stride' slots per atom,
// the first count[i] of them used; owners are the atoms 0 .. nowned-1.
struct PDBondTable {
  int nowned;             // atoms whose far ends are mapped
  int stride;             // slots per row
  const int *count;       // bonds stored by each atom
  const tagint *partner;  // far end of each bond, as a tag
  double *len0;           // reference length (negative: broken)
  const int *far;         // far end as a local index (owned + ghost)

  // the current length of atom i's k-th bond
  double length(double **x, int i, int k) const
  {
    const int j = far[i * stride + k];
    const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
    return sqrt(dx * dx + dy * dy + dz * dz);
  }
};

class PDFractureRecord : protected Pointers {
 public:
  explicit PDFractureRecord(class LAMMPS *);

  // -- totals: this rank's share (restart keeps the sums on rank 0) --
  // bonds this rank broke by fracture (not pre-cracks)
  void add_broken(bigint n)
  {
    nbroken += n;
    breaks_since_map += n;
  }
  // bonds this rank cut by a pre-crack: no fracture, but no longer intact
  void add_cut(bigint n) { breaks_since_map += n; }
  // energy dissipated in the bonds, as a sum of energy densities and in joules
  void add_dissipated(double e, double joule = 0.0)
  {
    dissipated += e;
    dissipated_joule += joule;
  }
  double local_dissipated() const { return dissipated; }
  double local_dissipated_joule() const { return dissipated_joule; }
  bigint local_broken() const { return nbroken; }
  // some bond anywhere is broken (pre-crack or fracture); the same on all ranks
  bool has_broken() const { return any_broken; }
  void set_has_broken() { any_broken = 1; }
  // breaks on this rank since the last call (the store's lost-bond count)
  bigint take_breaks_since_map()
  {
    const bigint n = breaks_since_map;
    breaks_since_map = 0;
    return n;
  }

  // -- the fresh-bond replay --
  // The bonds that broke at the last evaluation that broke any (or at the
  // last evaluation, none), by owner and partner tag, and their lengths
  // then; every rank holds them all. unbreak_fresh() makes them intact
  // again for a second evaluation of that step, if it is one and the atoms
  // are where they were (true: a replay); rebreak_fresh() breaks them after
  // it; note_fresh() records a new evaluation's breaks (len0 indices of
  // this rank; all ranks call it with the same 'any': some rank broke one).
  bool unbreak_fresh(const PDBondTable &bonds, bigint step);
  void rebreak_fresh(const PDBondTable &bonds);
  void note_fresh(const PDBondTable &bonds, const int *idx, int n, bigint step, bool any);

  // -- restart: the store writes these into its record --
  struct Totals {
    bigint broken;            // bonds broken by fracture, all ranks
    bigint breaks_since_map;  // breaks since the last mapping, all ranks
    double dissipated;        // sum of energy densities, all ranks
    double dissipated_joule;
    int any_broken;
    bigint fresh_step;
  };
  Totals sum_over_ranks() const;    // collective
  // every rank passes the same totals; rank 0 keeps the sums
  void restore(const Totals &t);
  const std::vector<tagint> &fresh_pairs() const { return pairs; }
  const std::vector<double> &fresh_lengths() const { return lengths; }
  void restore_fresh(std::vector<tagint> fresh_pairs, std::vector<double> fresh_lengths);

 private:
  bigint nbroken;            // bonds broken on this rank (fracture, not pre-cracks)
  bigint breaks_since_map;   // bonds this rank broke since the last mapping (fracture, pre-cracks)
  double dissipated;         // this rank's share of the dissipated energy
  double dissipated_joule;   // the same in joules
  int any_broken;            // some bond anywhere is broken (pre-crack or fracture)
  bigint fresh_step;         // the step of the last evaluation that broke bonds (or broke none)
  std::vector<tagint> pairs;     // its broken bonds, owner and partner tags, all ranks
  std::vector<double> lengths;   // the length of each when it broke

  void sign_fresh(const PDBondTable &bonds, double sign);
};

}    // namespace LAMMPS_NS

#endif
