/* PERI's rule (pd_law_legacy.h): what the LAMMPS side computes with the
 * kernels' arithmetic, compiled with the core's flags. */
#include "pd_law_legacy.h"

#include "pd_bond_loop.h"

double pd_law_legacy_note_of(double s00, double alpha, double s)
{
  return pd_law_legacy_note_value(s00, alpha, s);
}

/* Bond by bond through the loop's own load (pd_bond_load, as pd_force_bond
 * takes a bond): the same stretch to the bit. Legacy bonds never act once
 * broken (no recontact), so every intact bond notes, as in the loop. */
void pd_law_legacy_notes_at(const pd_bond_view *b, const int *type, int ntypes, const double *x,
                            const pd_law_legacy *p, double *note_atom, int nall)
{
  pd_failure fail;
  memset(&fail, 0, sizeof fail);
  fail.law = PD_FAIL_LEGACY;
  fail.params = p;
  for (int a = 0; a < nall; a++) note_atom[a] = -INFINITY;
  pd_bond bd;
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    const int trow = pd_row_begin(&bd, type, ntypes, i);
    const double xi[3] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
    for (int k = 0; k < b->count[i]; k++) {
      pd_bond_load(&bd, b, type, trow, x, xi, &fail, row + k, PD_WEIGHT_ONE, 1, 1);
      if (bd.broken) continue;
      const double value = pd_law_legacy_notes(&fail, &bd);
      pd_note_max(note_atom + i, value);
      pd_note_max(note_atom + bd.j, value);
    }
  }
}
