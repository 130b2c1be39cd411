/* Periodic lattices and the bond family of one site, for the exact
 * reference of linear waves (tools/pd_exact) and the lattice errors of the
 * constants (pd_dispersion.h).
 *
 * Each lattice is LAMMPS's (lattice sc/fcc/sq/hex with constant a) and is
 * held as the sites of an orthogonal grid of steps h[d]: every grid point
 * (chain, sq, sc) or those whose index sum is even (hex, fcc). A box of n
 * conventional cells per side is then a grid of n * sub[d] points per side,
 * which a plain FFT covers (the odd points carry no data). */
#ifndef PD_LATTICE_H
#define PD_LATTICE_H

#include "pd_influence.h"

typedef enum pd_lattice_kind {
  PD_LATTICE_CHAIN, /* 1D, step a */
  PD_LATTICE_SQ,    /* 2D square, step a */
  PD_LATTICE_HEX,   /* 2D triangular: LAMMPS hex, cell a x sqrt(3) a, 2 sites */
  PD_LATTICE_SC,    /* 3D simple cubic, step a */
  PD_LATTICE_FCC    /* 3D face-centred cubic, cubic cell a, 4 sites */
} pd_lattice_kind;

typedef struct pd_lattice {
  pd_lattice_kind kind;
  int dim;          /* 1, 2 or 3 */
  double a;         /* lattice constant as LAMMPS's lattice command takes it */
  double cell[3];   /* conventional cell sides (0 beyond dim) */
  int sub[3];       /* grid steps per cell side (1 beyond dim) */
  double h[3];      /* grid steps cell / sub (0 beyond dim) */
  int parity;       /* 1: only grid points with an even index sum are sites */
  double volume;    /* length^dim per site (area in 2D, length in 1D) */
  double nearest;   /* nearest-neighbour distance */
} pd_lattice;

/* 0 on success, -1 for a bad kind or a <= 0. */
int pd_lattice_make(pd_lattice_kind kind, double a, pd_lattice *out);

/* LAMMPS's names (chain, sq, hex, sc, fcc) <-> kind; -1 if unknown. */
int pd_lattice_from_name(const char *name);
const char *pd_lattice_name(pd_lattice_kind kind);

/* A bond's quadrature weight (influence x partial volume, ...): the same
 * number the bond store keeps per bond. */
typedef double (*pd_weight_fn)(const double xi[3], double r, void *ctx);

/* The weight of pair_style pd/ordinary: omega(|xi|) of an influence
 * function (ctx: a pd_influence_weight). */
typedef struct pd_influence_weight {
  pd_influence_kind kind;
  int dim;
  double horizon;
} pd_influence_weight;
double pd_influence_weight_fn(const double xi[3], double r, void *ctx);

typedef struct pd_family_bond {
  double xi[3]; /* bond vector x' - x */
  double r;     /* |xi| */
  double w;     /* weight (1 without a weight function) */
  int p[3];     /* xi in grid steps */
} pd_family_bond;

/* The family of one site: every site with 0 < |xi| <= cutoff (as fix
 * pd/bonds takes them, r <= horizon; a site on the cutoff to within 1e-12
 * relative counts, so that round-off in a product like 3 * a does not
 * decide), in +-pairs, and the volume of every partner. The cutoff is the
 * horizon, or farther for a quadrature whose cells reach past it (the
 * weight function then knows the horizon); a bond whose weight is 0 is
 * left out (it adds nothing to any sum). */
typedef struct pd_family {
  int dim, n;
  double volume;       /* partner volume: site volume (x thickness in 2D) */
  pd_family_bond *bond;
} pd_family;

/* Build the family (allocates bond; free with pd_family_free). weight may be
 * NULL (every weight 1, no bond left out). thickness multiplies the site volume in 2D (the
 * volume LAMMPS's 2D atoms carry), ignored otherwise. Returns the number of
 * bonds, or -1 (bad arguments, no memory). */
int pd_lattice_family(const pd_lattice *lat, double cutoff, double thickness, pd_weight_fn weight,
                      void *ctx, pd_family *out);
void pd_family_free(pd_family *f);

/* Weighted volume m = sum w V over the family: the per-atom sum the bond
 * store computes (pd_weighted_volume) for a complete family. */
double pd_family_weighted_volume(const pd_family *f);

/* sum w V |xi|^power over the family: what pd_family_moment sums per atom
 * in the bond store, for a complete family. */
double pd_family_moment_sum(const pd_family *f, int power);

#endif
