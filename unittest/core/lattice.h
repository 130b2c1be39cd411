/* A simple-cubic block of material points with its bond families, built by
 * brute force, for testing the core kernels without LAMMPS. */
#ifndef PD_TEST_LATTICE_H
#define PD_TEST_LATTICE_H

#include "pd_bonds.h"
#include "pd_influence.h"

typedef struct lattice {
  int n, natoms, stride;
  double h, delta;
  double *x0, *vol;
  int *type;
  int *count, *far;
  double *len0, *weight;
  double *reaction;   /* the force loop's scratch (pd_loop.reaction): 4 per atom, zero */
} lattice;

/* n^3 points (n^2 when dim == 2, z = 0) with spacing h; bonds within delta,
 * each stored at its lower-index end; weight = omega(|xi|) or NULL if
 * kind < 0. */
lattice lattice_make(int dim, int n, double h, double delta, int kind);
void lattice_free(lattice *l);
pd_bond_view lattice_view(const lattice *l);
int lattice_center(const lattice *l);

/* The 3x3 arguments are not const: ISO C before C23 does not convert a
 * double[3][3] argument to a const one without a cast. */

/* Displacement of a uniform small strain eps (3x3, symmetric) about x0. */
void lattice_strain(const lattice *l, double eps[3][3], double *x);

/* Rigid rotation of positions and vectors by the rotation matrix R. */
void rotate(double R[3][3], int n, const double *in, double *out);
void rotation_matrix(double ax, double ay, double az, double R[3][3]);

/* Deterministic uniform random numbers in [-1, 1). */
double urand(unsigned *state);

#endif
