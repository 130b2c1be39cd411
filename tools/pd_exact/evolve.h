/* The exact solution in Fourier space: each mode of the lattice is an
 * eigenmode of the linear operator (EW06 section 3), so with
 * W = sqrt(A(k)/rho) (a symmetric eigen-decomposition of A(k))
 *   u_k(t) = cos(W t) u_k(0) + W^-1 sin(W t) v_k(0),
 *   v_k(t) = -W sin(W t) u_k(0) + cos(W t) v_k(0). */
#ifndef PD_EXACT_EVOLVE_H
#define PD_EXACT_EVOLVE_H

#include "setup.h"
#include "sites.h"

#include <stdio.h>

/* Advance s->u, s->v (on the grid) by p->time. 0, or -1 with the reason
 * (an unstable mode: A(k) not positive) printed to err. */
int exact_evolve(const exact_problem *p, exact_sites *s, FILE *err);

/* The wave vector of grid mode m (0 <= m[d] < grid[d]), centred in the
 * first zone of the grid; for a lattice with parity (hex, fcc) the
 * shorter of k and its alias k + (pi/h0, pi/h1, pi/h2), which carries the
 * same data: the classical solution takes the long wave of each pair. */
void exact_wave_vector(const exact_problem *p, const int m[3], double k[3]);

#endif
