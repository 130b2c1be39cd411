/* The key-value input file of pd_exact (README.md lists the keys). */
#ifndef PD_EXACT_INPUT_H
#define PD_EXACT_INPUT_H

#include <stdio.h>

typedef struct exact_input {
  char lattice[16];     /* chain, sq, hex, sc, fcc */
  int dim;              /* 0 if not given (taken from the lattice) */
  int n[3];             /* conventional cells per side */
  double spacing;       /* LAMMPS lattice constant */
  double horizon;
  char model[16];       /* pmb, ordinary, classical */
  /* material constants as pair_coeff takes them; NaN when not given */
  double K, G, E, nu, c;
  double density;
  char influence[32];   /* "" = pd/ordinary's default */
  char plane[16];       /* stress or strain (2D) */
  char quadrature[16];  /* point (default) or partial */
  char directional[8];  /* yes (default) or no: the pair styles' directional_correction */
  double thickness;     /* 2D: plate thickness (default 1) */
  double time;
  double origin[3];     /* position of grid point (0, 0, 0) */
  char fields[1024], output[1024];
} exact_input;

/* Reads 'path'; on a bad line or a missing key prints why to 'err' and
 * returns -1. */
int exact_read_input(const char *path, exact_input *in, FILE *err);

#endif
