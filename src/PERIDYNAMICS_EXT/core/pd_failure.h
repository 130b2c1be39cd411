/* Bond failure (MS07 eq. 25-31; T14 ch. 6): the state every failure law
 * shares. The laws themselves are in pd_law_<name>.h (listed in pd_laws.h).
 *
 * A broken bond is stored with a negative reference length: the sign is the
 * one bit of failure state, so a scene without failure keeps no extra
 * per-bond memory. With recontact (the default, T14 6.1.3) a broken bond
 * still acts while it is compressed; without it, it never acts again. */
#ifndef PD_FAILURE_H
#define PD_FAILURE_H

#include "pd_bonds.h"
#include "pd_laws.h"

#include <math.h>

static inline int pd_bond_broken(double len0) { return len0 < 0.0; }

typedef struct pd_failure {
  pd_fail_law law;
  const void *params;     /* the law's parameters (pd_law_<name>.h), or NULL */
  int recontact;          /* broken bonds still push in compression */
  /* with recontact: per-atom contact radius (owned + ghost; half the
   * particle spacing), or NULL for a broken bond to push at any length */
  const double *contact_radius;
  double *len0;           /* the bonds' reference lengths, written on breaking */
  double *released_atom;  /* per-atom released energy density (owned + ghost), or NULL */
  /* the law's per-atom notes (owned + ghost), written by the force loop:
   * each intact bond that acted offers a value to both ends, which keep
   * the largest (-inf where none); NULL for a law that notes nothing */
  double *note_atom;
  /* a law whose kernels keep only the largest note (PD_NOTES_LARGEST):
   * the largest of the call, written by it (-inf where no bond noted) */
  double note_largest;
  double released;        /* added by each call: sum of energy densities released */
  double released_joule;  /* the same in joules (volume-weighted) */
  long nbroken;           /* bonds broken by each call */
  /* the bonds this call broke with half their force (indices into len0),
   * kept so that the step can be evaluated again (the first evaluation of
   * a next run, or after a restart) with the same forces; grown by
   * realloc, owned by the caller */
  int *fresh;
  int nfresh, maxfresh;
  /* 1: this call evaluates again the step in which the listed bonds broke
   * (the caller made them intact again): they break as before, and nothing
   * is booked twice */
  int replay;
} pd_failure;

/* Append idx to f->fresh, growing it (0 when out of memory). */
int pd_failure_note_fresh(pd_failure *f, int idx);

/* The smallest of n per-atom values (+inf for none; NaNs skipped): a law's
 * floor for its screen, pd_law_<name>_ahead (pd_laws.h). */
double pd_failure_floor(const double *value, int n);

/* The reference length a bond acts with, and whether it is broken. A
 * broken bond pushes only once its two particles touch, as MS07's
 * short-range force: its reference length becomes the contact distance
 * r_i + r_j where that is shorter, so its force rises from zero there and
 * faces apart by more than that exert none on each other. */
static inline double pd_bond_reference(const pd_failure *f, double len0, int i, int j, int *broken)
{
  *broken = pd_bond_broken(len0);
  const double r0 = fabs(len0);
  if (!*broken || !f->contact_radius) return r0;
  const double touch = f->contact_radius[i] + f->contact_radius[j];
  return touch < r0 ? touch : r0;
}

/* A broken bond acts only while compressed (strain < 0 with the reference
 * length above), and only with recontact. */
static inline int pd_bond_inactive(const pd_failure *f, int broken, double strain)
{
  return broken && (strain >= 0.0 || !f->recontact);
}

/* Sums a kernel keeps while it breaks bonds, added to the pd_failure at the end. */
typedef struct pd_break_sums {
  double released, released_joule;
  long nbroken;
} pd_break_sums;

/* Break a bond: flip the sign of its length and book the energy it
 * releases, ei at i and ej at j per unit volume of the partner. 'fresh':
 * it breaks with half its force, so a second evaluation of this step must
 * find it intact again (pd_failure.fresh). */
static inline void pd_break_bond(pd_failure *f, pd_break_sums *sums, const pd_bond *bd, double ei,
                                 double ej, double vi, double vj, int fresh)
{
  f->len0[bd->idx] = -bd->r0;
  if (f->replay) return;
  if (fresh) pd_failure_note_fresh(f, bd->idx);
  sums->nbroken++;
  sums->released += ei * vj + ej * vi;
  sums->released_joule += (ei + ej) * vi * vj;
  if (f->released_atom) {
    f->released_atom[bd->i] += ei * vj;
    f->released_atom[bd->j] += ej * vi;
  }
}

static inline void pd_add_break_sums(pd_failure *f, const pd_break_sums *sums)
{
  f->released += sums->released;
  f->released_joule += sums->released_joule;
  f->nbroken += sums->nbroken;
}

#endif
