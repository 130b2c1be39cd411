/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: what pd/contact keeps between reneighborings.

   The candidates: the pairs of pd/contact's neighbor list that may touch,
   each with its contact distance, taken when LAMMPS reneighbors. The short
   list: the candidates closer than their contact distance plus a small
   skin of its own, taken again whenever an atom of a candidate moved more
   than half that skin since the last time, and after every reneighboring
   (core/pd_contact_list.h). Atom indices, owned and ghost, do not change
   between reneighborings, so the check needs no communication. The force
   loop visits the short list only: the pairs in contact, in the order of
   the candidates.
------------------------------------------------------------------------- */

#ifndef LMP_PD_CONTACT_CACHE_H
#define LMP_PD_CONTACT_CACHE_H

#include "pointers.h"

extern "C" {
#include "pd_contact_list.h"
}

namespace LAMMPS_NS {

class PDContactCache : protected Pointers {
 public:
  explicit PDContactCache(class LAMMPS *);
  ~PDContactCache() override;

  // -- taking the candidates (at reneighboring) --
  void clear() { ncand = 0; }
  void add(int i, int j, double dist)
  {
    if (ncand == maxcand) grow();
    cand[ncand++] = {i, j, dist};
  }
  // the candidates are complete: take the short list with this skin (0:
  // none, every candidate is visited at every step)
  void settle(double skin_short);

  // -- every step --
  // take the short list again if an atom moved more than half its skin
  void refresh();
  const pd_contact_cand *pairs() const { return skin > 0.0 ? nearby : cand; }
  int npairs() const { return skin > 0.0 ? nnear : ncand; }

  const pd_contact_cand *candidates() const { return cand; }
  int ncandidates() const { return ncand; }
  double memory_usage() const;

 private:
  pd_contact_cand *cand, *nearby;    // the candidates; the short list
  int ncand, maxcand, nnear, maxnear;
  double skin;                     // the short list's skin (0: no short list)
  int *atoms, natoms, maxatoms;    // the atoms of the candidates, each once
  double *ref;                     // their positions at the last short list
  int *seen, maxseen;              // per local atom: listed in atoms[]

  void grow();
  void take();
};

}    // namespace LAMMPS_NS

#endif
