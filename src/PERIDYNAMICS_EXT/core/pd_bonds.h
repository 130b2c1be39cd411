/* The bond arrays every kernel walks: each bond is stored once, at the atom
 * that owns it, and visited once (Newton's third law gives the far end). */
#ifndef PD_BONDS_H
#define PD_BONDS_H

#include <stddef.h>

/* PD_INLINE for the kernels (pd_ordinary.c, pd_bond_based.c), which include
 * this header through their own. */
#include "pd_macros.h"

typedef struct pd_bond_view {
  int nowner;            /* atoms 0 .. nowner-1 may own bonds */
  int stride;            /* row length of the per-atom bond tables */
  const int *count;      /* count[i]: bonds owned by atom i */
  const int *far;        /* far[i*stride + k]: local index of the far end */
  const double *len0;    /* reference bond length |xi| */
  const double *weight;  /* per-bond quadrature weight (influence x partial
                            volume), or NULL when every weight is 1 */
  /* > 0: every weight is weight_horizon * (1 / |xi|) (the inverse influence with
   * point quadrature, one horizon), and the force and current-sum loops
   * compute it instead of loading it: the same number, and 8 bytes less
   * per bond and pass to stream (pd/ordinary 64^3: 1.1x). 0: they load
   * weight. */
  double weight_horizon;
} pd_bond_view;

/* One bond as the bond loops (pd_bond_loop.h) hand it to a material and a
 * failure law. */
typedef struct pd_bond {
  int i, j;        /* owner and far end (local indices) */
  int idx;         /* its slot in the bond tables */
  int ti, tj;      /* their types */
  int tij;         /* ti * ntypes + tj: the bond's entry in a type-pair table */
  int broken;      /* broken: acts only in compression (recontact) */
  double r0;       /* reference length it acts with */
  double w;        /* quadrature weight (1 without weights) */
  double len;      /* current length (not set in reference walks) */
  double len2;     /* its square, |Y|^2: the strains of m = 0 and negative
                      integer m take no square root (the compiler drops
                      len where nothing reads it) */
  double d[3];     /* x_j - x_i (not set in reference walks) */
} pd_bond;

/* One reciprocal per bond, 1/(|xi| |Y|) (0 for a bond of zero length):
 * 1/|xi| = |Y| q and 1/|Y| = |xi| q. Materials and failure laws that take
 * the stretch and the force per length from it share its one divide (the
 * compiler merges identical expressions): the vector divider is what
 * bounds the bond loop. */
PD_INLINE double pd_bond_inverse(const pd_bond *bd)
{
  return bd->len > 0.0 ? 1.0 / (bd->r0 * bd->len) : 0.0;
}

/* The stretch (|Y| - |xi|) / |xi| through pd_bond_inverse (-1 at zero
 * length). */
PD_INLINE double pd_bond_stretch(const pd_bond *bd)
{
  return bd->len > 0.0 ? (bd->len - bd->r0) * (bd->len * pd_bond_inverse(bd)) : -1.0;
}

/* A force state t per unit current length (0 at zero length). */
PD_INLINE double pd_per_length(double t, const pd_bond *bd)
{
  return bd->len > 0.0 ? t / bd->len : 0.0;
}

/* What a material answers for one bond of strain eps. */
typedef struct pd_bond_force {
  double tl;                   /* force state over the current length, t / |Y|:
                                  f_i += V_j tl Y, f_j -= V_i tl Y (Y = x_j - x_i) */
  double stored;               /* energy density it stores at each end, per
                                  unit volume of the partner, before that
                                  end's factor (pd_loop.energy_scale; tallied) */
  double release_i, release_j; /* what it releases at each end if it breaks now */
  double release;              /* their sum, as the energy law tests it: in
                                  the material's cheapest form (pd/ordinary's
                                  shares the force's sums of both ends) */
  double v[3];                 /* a directed material's force instead of t (not
                                  along the bond): f_i += V_j v, f_j -= V_i v */
} pd_bond_force;

/* Weighted volume over every bond, at both ends: m_i += w V_j, m_j += w V_i
 * (w = 1 without weights: the family volume). */
void pd_weighted_volume(const pd_bond_view *b, const double *vol, double *m);

/* The family volume (w = 1) and the weighted volume together, in one pass
 * over the bonds (either may be NULL): the same sums, in the same order. */
void pd_reference_volumes(const pd_bond_view *b, const double *vol, double *family, double *weighted);

/* The same over intact bonds only (a broken bond has a negative length). */
void pd_intact_volume(const pd_bond_view *b, const double *vol, double *m);

/* Energy and virial, gathered only on steps that ask for them.
 * energy: sum of per-atom energy densities (the PERI convention);
 * virial: sum of (x_i - x_j) (x) F_ij with F_ij = V_i V_j (force state),
 * a true force, so virial / box volume is a stress, as in PERI;
 * eatom: per-atom energy density over owned and ghost atoms, or NULL;
 * skip_virial: the step asks for no global virial (compute pe/atom), it
 * is left at zero;
 * vatom: per-atom virial over owned and ghost atoms (6 each, xx yy zz xy
 * xz yz: LAMMPS's), or NULL: each pair's (x_i - x_j) (x) F_ij, half to
 * each end (pd_atom_virial_share), so that the atoms' sum is the global
 * virial and compute stress/atom / V_i is a stress;
 * own_virial: a bond loop's row tally keeps its owner's share there, added
 * to vatom at the row's end (pd_bond_loop.h). */
typedef struct pd_tally {
  double energy;
  double virial[6];
  double *eatom;
  int skip_virial;
  double *vatom;
  double own_virial[6];
} pd_tally;

/* Each end's half of a pair's (x_i - x_j) (x) F_ij, r = x_i - x_j and F
 * the true force on i, as w (xx yy zz xy xz yz). Symmetrized: a force not
 * along the pair (pd/corr classical) has no symmetric tensor of its own,
 * and the global virial takes the symmetric part too. */
static inline void pd_atom_virial_share(const double r[3], const double F[3], double w[6])
{
  w[0] = 0.5 * r[0] * F[0];
  w[1] = 0.5 * r[1] * F[1];
  w[2] = 0.5 * r[2] * F[2];
  w[3] = 0.25 * (r[0] * F[1] + r[1] * F[0]);
  w[4] = 0.25 * (r[0] * F[2] + r[2] * F[0]);
  w[5] = 0.25 * (r[1] * F[2] + r[2] * F[1]);
}

/* The pair's shares onto i's per-atom virial (own, 6) and j's (in vatom);
 * the bond loops' 4-wide form is pd_bond_loop.h's. */
static inline void pd_tally_atom_virial(double *vatom, double *own, int j,
                                        const double r[3], const double F[3])
{
  double w[6];
  pd_atom_virial_share(r, F, w);
  for (int c = 0; c < 6; c++) {
    own[c] += w[c];
    vatom[6 * (ptrdiff_t) j + c] += w[c];
  }
}

/* Add a pair's virial, fpair being the force on i per unit d = x_i - x_j:
 * the global one (unless skip_virial) and the per-atom one (when vatom). */
static inline void pd_tally_virial(pd_tally *t, int i, int j, const double d[3], double fpair)
{
  if (t->vatom) {
    const double F[3] = {d[0] * fpair, d[1] * fpair, d[2] * fpair};
    pd_tally_atom_virial(t->vatom, t->vatom + 6 * (ptrdiff_t) i, j, d, F);
  }
  if (t->skip_virial) return;
  t->virial[0] += d[0] * d[0] * fpair;
  t->virial[1] += d[1] * d[1] * fpair;
  t->virial[2] += d[2] * d[2] * fpair;
  t->virial[3] += d[0] * d[1] * fpair;
  t->virial[4] += d[0] * d[2] * fpair;
  t->virial[5] += d[1] * d[2] * fpair;
}

#endif
