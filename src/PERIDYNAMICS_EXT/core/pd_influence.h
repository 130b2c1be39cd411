/* Influence functions, in the convention of T14 eq. 5.1: omega weights the
 * bond strain directly, tr_omega(eps) = sum omega eps V. Each is declared
 * once in pd_influence.c (its formula, name and properties); to add one,
 * write its function there, add its line to the table and its kind here. */
#ifndef PD_INFLUENCE_H
#define PD_INFLUENCE_H

typedef enum pd_influence_kind {
  PD_INFLUENCE_CONSTANT, /* omega = 1 */
  PD_INFLUENCE_INVERSE,  /* omega = delta / |xi| */
  PD_INFLUENCE_LPS,      /* omega = |xi| / delta: peri/lps's 1/|xi| in the
                            weighted-volume convention (omega |xi|^2) */
  PD_INFLUENCE_TUPEK,    /* T14 eq. 6.6 (2D) and 6.7 (3D) polynomial */
  PD_INFLUENCE_GAUSS     /* exp(-|xi|^2 / sigma^2), sigma = delta / 2 */
} pd_influence_kind;

/* omega(r) for 0 < r <= delta in dimension dim (2 or 3); 0 beyond delta. */
double pd_influence(pd_influence_kind kind, int dim, double r, double delta);

/* omega of a partner whose cell reaches inside the horizon (partial-volume
 * quadrature): its value at min(r, delta), since a partner centred beyond
 * the horizon counts by the part of its cell inside it. */
double pd_influence_of_cell(pd_influence_kind kind, int dim, double r, double delta);

/* 1 if omega ~ 1/r at the origin (the 2D G_c integral diverges). */
int pd_influence_singular(pd_influence_kind kind);

/* Name <-> kind for input parsing and logs; -1 for an unknown name. */
int pd_influence_from_name(const char *name);
const char *pd_influence_name(pd_influence_kind kind);
/* All names, comma separated, for messages. */
const char *pd_influence_names(void);

/* Legacy PERI's partial-volume factor: a neighbor whose distance is within
 * half a lattice spacing lc of the horizon counts with a linearly reduced
 * volume (LAMMPS peri/pmb, peri/lps). */
double pd_partial_volume_legacy(double r, double delta, double lc);

#endif
