/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: the declaration of a per-atom field held by the bond
   store (fix pd/bonds). Whoever needs per-atom state declares it once
   (name, width, what the store does with it); the store owns the storage
   (owned + ghost atoms, 'width' doubles per atom, atom i at i * width),
   grows it with the atoms, and communicates, migrates, restarts and
   outputs it as the flags say.
------------------------------------------------------------------------- */

#ifndef LMP_PD_FIELD_H
#define LMP_PD_FIELD_H

#include <string>

namespace LAMMPS_NS {

struct PDField {
  enum Flags {
    FORWARD = 1,    // ghosts need it: forward(id) copies owners to ghosts
    MIGRATE = 2,    // it belongs to the atom: moves with it to another processor
    RESTART = 4,    // written to restart files, read back by name
    OUTPUT = 8,     // listed by compute pd/atom under its name
    ON_DEMAND = 16  // an output computed only when a compute pd/atom listing
                    // it is due (PairPD::demanded), not on every step
  };
  std::string name;
  int width;    // doubles per atom (1 scalar, 2 a pair, 9 a tensor, ...)
  int flags;    // or-ed Flags
};

}    // namespace LAMMPS_NS

#endif
