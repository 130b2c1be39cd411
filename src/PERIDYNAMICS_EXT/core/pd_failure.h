/* Bond failure (MS07 eq. 25-31; T14 ch. 6): laws, calibration, and the
 * state a failure-aware kernel updates.
 *
 * A broken bond is stored with a negative reference length: the sign is the
 * one bit of failure state, so a scene without failure keeps no extra
 * per-bond memory. With recontact (the default, T14 6.1.3) a broken bond
 * still acts while it is compressed; without it, it never acts again. */
#ifndef PD_FAILURE_H
#define PD_FAILURE_H

#include "pd_bonds.h"

#include <math.h>
#include "pd_influence.h"

/* PD_FAIL_LEGACY is LAMMPS PERI's rule: a bond breaks after its force acts
 * when its stretch exceeds min(s0_i, s0_j) of the previous step, and each
 * atom's s0 becomes max over its intact bonds of (s00 - alpha stretch). */
typedef enum pd_fail_law { PD_FAIL_NONE, PD_FAIL_STRETCH, PD_FAIL_ENERGY, PD_FAIL_LEGACY } pd_fail_law;

static inline int pd_bond_broken(double len0) { return len0 < 0.0; }

typedef struct pd_failure {
  pd_fail_law law;
  int recontact;          /* broken bonds still push in compression */
  /* with recontact: per-atom contact radius (owned + ghost; half the
   * particle spacing), or NULL for a broken bond to push at any length */
  const double *contact_radius;
  const double *s0;       /* critical stretch per type pair (stretch law) */
  double *len0;           /* the bonds' reference lengths, written on breaking */
  double *released_atom;  /* per-atom released energy density (owned + ghost), or NULL */
  double released;        /* added by each call: sum of energy densities released */
  double released_joule;  /* the same in joules (volume-weighted) */
  long nbroken;           /* bonds broken by each call */
  /* legacy rule only: per type pair s00 (in s0) and alpha; per atom the s0
   * of the previous step (owned + ghost) and the new s0 (a max over both
   * ends, -inf where no intact bond was seen) */
  const double *alpha;
  const double *s0_atom;
  double *s0_new;
  /* the bonds this call broke (indices into len0), kept so that the step
   * can be evaluated again (the first evaluation of a next run, or after a
   * restart) with the same forces; grown by realloc, owned by the caller */
  int *fresh;
  int nfresh, maxfresh;
  /* 1: this call evaluates again the step in which the listed bonds broke
   * (the caller made them intact again): they break as before, and nothing
   * is booked twice */
  int replay;
} pd_failure;

/* Append idx to f->fresh, growing it (0 when out of memory). */
int pd_failure_note_fresh(pd_failure *f, int idx);

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

/* Break bond idx between i and j: flip the sign of its length and book the
 * energy it releases, ei at i and ej at j per unit volume of the partner. */
static inline void pd_break_bond(pd_failure *f, pd_break_sums *sums, int idx, double r0, int i,
                                 int j, double ei, double ej, double vi, double vj)
{
  f->len0[idx] = -r0;
  if (f->replay) return;
  if (f->law != PD_FAIL_LEGACY) pd_failure_note_fresh(f, idx);
  sums->nbroken++;
  sums->released += ei * vj + ej * vi;
  sums->released_joule += (ei + ej) * vi * vj;
  if (f->released_atom) {
    f->released_atom[i] += ei * vj;
    f->released_atom[j] += ej * vi;
  }
}

static inline void pd_add_break_sums(pd_failure *f, const pd_break_sums *sums)
{
  f->released += sums->released;
  f->released_joule += sums->released_joule;
  f->nbroken += sums->nbroken;
}

/* The legacy rule for one intact bond of stretch s between i and j after
 * its force acted: returns 1 if it breaks; updates the new s0 of both ends. */
static inline int pd_legacy_failure(const pd_failure *f, int tij, int i, int j, double s)
{
  const double cand = f->s0[tij] - f->alpha[tij] * s;
  if (cand > f->s0_new[i]) f->s0_new[i] = cand;
  if (cand > f->s0_new[j]) f->s0_new[j] = cand;
  const double lim = f->s0_atom[i] < f->s0_atom[j] ? f->s0_atom[i] : f->s0_atom[j];
  return s > lim;
}

/* Energy-based failure (T14 eq. 6.1-6.3): s_c(xi) = beta omega |xi|^-2 with
 * omega the influence function normalized to integrate to d over the
 * horizon. Cutting every bond across a unit area releases, bond by bond,
 * s_c at both ends: G_c = 2 I with I = pi int_0^delta r omega dr (3D) or
 * 2 int_0^delta omega dr (2D), integrated numerically here. Returns beta
 * for a given G_c, or a negative value when the integral diverges (the 2D
 * inverse influence). */
double pd_energy_failure_beta(pd_influence_kind kind, int dim, double delta, double Gc);

/* The same calibration on the lattice actually used: the sum over a
 * complete family replaces the integral, and the crack orientation is
 * averaged (the mean of max(cos, 0) is 1/pi in 2D, 1/4 in 3D), so that
 * cutting bonds across a plane of any orientation releases G_c on average:
 * G = 2 beta N <cos+> sum w V / |xi|, N = d / (sum w V). The sums are those
 * of one complete family: its weighted volume and pd_failure_moment. On a
 * simple cubic or square lattice a crack along the lattice axes then
 * releases 0.94-0.97 G_c (delta = 3-6 spacings); the continuum calibration
 * above gives 0.76 G_c in 2D at delta = 3 spacings with a constant omega. */
double pd_energy_failure_beta_lattice(int dim, double Gc, double weighted_volume, double moment);

/* sum w V_other / |xi| over both ends of every bond (broken or not). */
void pd_failure_moment(const pd_bond_view *b, const double *vol, double *moment);

/* Critical stretch from the fracture energy for bond-based elasticity
 * (MS07 eq. 28-29 and the 2D analogues in THEORY.md): 3D sqrt(5 G / (9 K
 * delta)) with K = E / (3 (1 - 2 nu)), plane stress sqrt(4 pi G / (9 E delta)),
 * plane strain sqrt(5 pi G / (12 E delta)). dim: 3, or 2 with plane = 0
 * (stress) or 1 (strain). */
double pd_critical_stretch(int dim, int plane_strain, double E, double nu, double delta, double Gc);

#endif
