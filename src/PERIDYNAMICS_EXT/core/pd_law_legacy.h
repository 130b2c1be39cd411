/* LAMMPS PERI's rule (legacy mode): a bond breaks after its force acted
 * when its stretch exceeds min(s0_i, s0_j) of the previous step, and each
 * atom's s0 becomes max over its intact bonds of (s00 - alpha stretch). */
#ifndef PD_LAW_LEGACY_H
#define PD_LAW_LEGACY_H

#include "pd_failure.h"
#include "pd_law_none.h"

typedef struct pd_law_legacy {
  const double *s00;      /* per type pair */
  const double *alpha;    /* per type pair */
  const double *s0_atom;  /* per atom s0 of the previous step (owned + ghost) */
  double s0_floor;        /* the smallest of them */
} pd_law_legacy;
/* Its notes (pd_failure.note_atom) are each atom's new s0: -inf where no
 * intact bond was seen. */

/* (a bond breaks only after its force acted: nothing before) */
#define pd_law_legacy_now pd_law_none_now

PD_INLINE int pd_law_legacy_after(const pd_failure *f, const pd_bond *bd, double eps)
{
  (void) eps;
  const pd_law_legacy *p = (const pd_law_legacy *) f->params;
  const double s = pd_bond_stretch(bd);
  const double lim = p->s0_atom[bd->i] < p->s0_atom[bd->j] ? p->s0_atom[bd->i] : p->s0_atom[bd->j];
  return s > lim;
}

/* _after against the smallest s0 of all atoms: no per-atom load */
PD_INLINE int pd_law_legacy_ahead(const pd_failure *f, const pd_bond *bd, double eps,
                                      const pd_bond_force *bf)
{
  (void) eps, (void) bf;
  const pd_law_legacy *p = (const pd_law_legacy *) f->params;
  return pd_bond_stretch(bd) > p->s0_floor;
}

PD_INLINE int pd_law_legacy_takes_notes(void) { return PD_NOTES_ENDS; }

/* A bond's candidate s0 at stretch s */
PD_INLINE double pd_law_legacy_note_value(double s00, double alpha, double s)
{
  return s00 - alpha * s;
}

/* every intact bond that acted: the candidate s0 of both ends */
PD_INLINE double pd_law_legacy_notes(const pd_failure *f, const pd_bond *bd)
{
  const pd_law_legacy *p = (const pd_law_legacy *) f->params;
  const int tij = bd->tij;
  return pd_law_legacy_note_value(p->s00[tij], p->alpha[tij], pd_bond_stretch(bd));
}

/* pd_law_legacy_note_value compiled in the core (-ffp-contract=off), so
 * that the LAMMPS side gets the kernels' number to the bit. */
double pd_law_legacy_note_of(double s00, double alpha, double s);

/* The notes of an evaluation at positions x (owned + ghost): note_atom
 * (nall) gets each atom's largest pd_law_legacy_notes over its intact
 * bonds, -inf where none, the numbers the kernels give there; type as
 * pd_loop.type (NULL: one type), ntypes its row length. */
void pd_law_legacy_notes_at(const pd_bond_view *b, const int *type, int ntypes, const double *x,
                            const pd_law_legacy *p, double *note_atom, int nall);

/* PERI's rule, guarded: an evaluation that skips the exact test and the
 * notes when it can prove afterwards that no bond broke ('fail legacy' on
 * the LAMMPS side decides). Its kernels break nothing and keep only the
 * largest stretch of the evaluation (pd_failure.note_largest): if that is
 * at most every atom's s0, no bond met PERI's test; else the evaluation
 * is made again with the exact law, adding no forces. No parameters. */
/* (breaking nothing, its tests are those of no law) */
#define pd_law_legacy_guarded_now pd_law_none_now
#define pd_law_legacy_guarded_after pd_law_none_after
#define pd_law_legacy_guarded_ahead pd_law_none_ahead

PD_INLINE int pd_law_legacy_guarded_takes_notes(void) { return PD_NOTES_LARGEST; }

PD_INLINE double pd_law_legacy_guarded_notes(const pd_failure *f, const pd_bond *bd)
{
  (void) f;
  return pd_bond_stretch(bd);
}

#endif
