/* The per-site fields: read "x y z ux uy uz vx vy vz" lines, place each on
 * its grid point, write the result in the input's order. */
#ifndef PD_EXACT_SITES_H
#define PD_EXACT_SITES_H

#include "setup.h"

#include <stdio.h>

typedef struct exact_sites {
  int n;          /* sites read */
  double *x;      /* 3 per site, as read */
  long *slot;     /* grid index of each site */
  long ngrid;     /* grid points: grid[0] grid[1] grid[2] */
  double *u, *v;  /* 3 per grid point (zero where no site is) */
} exact_sites;

/* 0, or -1 with the reason (a position off the lattice, a site given
 * twice, a site missing) printed to err. */
int exact_read_sites(const char *path, const exact_problem *p, const double origin[3],
                     exact_sites *s, FILE *err);
int exact_write_sites(const char *path, const exact_sites *s, double time, FILE *err);
void exact_free_sites(exact_sites *s);

#endif
