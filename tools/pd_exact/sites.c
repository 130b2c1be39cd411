#include "sites.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Grid index of a position, or -1 if it is not within 1e-6 steps of a
 * site (positions may be periodic images: folded into the box). */
static long grid_slot(const exact_problem *p, const double origin[3], const double x[3])
{
  long idx = 0, sum = 0;
  for (int d = 0; d < 3; d++) {
    long i = 0;
    if (d < p->lat.dim) {
      const double q = (x[d] - origin[d]) / p->lat.h[d];
      const double r = floor(q + 0.5);
      if (fabs(q - r) > 1e-6) return -1;
      i = ((long) r % p->grid[d] + p->grid[d]) % p->grid[d];
    }
    sum += i;
    idx = idx * p->grid[d] + i;
  }
  if (p->lat.parity && sum % 2) return -1;
  return idx;
}

int exact_read_sites(const char *path, const exact_problem *p, const double origin[3],
                     exact_sites *s, FILE *err)
{
  memset(s, 0, sizeof(*s));
  s->ngrid = (long) p->grid[0] * p->grid[1] * p->grid[2];
  const long nsites = p->lat.parity ? s->ngrid / 2 : s->ngrid;
  FILE *fp = fopen(path, "r");
  if (!fp) {
    fprintf(err, "pd_exact: cannot open fields file '%s'\n", path);
    return -1;
  }
  s->x = malloc(sizeof(double) * 3 * nsites);
  s->slot = malloc(sizeof(long) * nsites);
  s->u = calloc(3 * s->ngrid, sizeof(double));
  s->v = calloc(3 * s->ngrid, sizeof(double));
  char *seen = calloc(s->ngrid, 1);
  char line[1024];
  int lineno = 0, bad = 0;
  while (!bad && fgets(line, sizeof line, fp)) {
    lineno++;
    char *hash = strchr(line, '#');
    if (hash) *hash = 0;
    double a[9];
    const int got = sscanf(line, "%lf %lf %lf %lf %lf %lf %lf %lf %lf", a, a + 1, a + 2, a + 3, a + 4,
                           a + 5, a + 6, a + 7, a + 8);
    if (got <= 0) continue;
    const long g = got == 9 ? grid_slot(p, origin, a) : -1;
    if (got != 9) fprintf(err, "pd_exact: %s:%d: expected x y z ux uy uz vx vy vz\n", path, lineno);
    else if (g < 0) fprintf(err, "pd_exact: %s:%d: (%g, %g, %g) is not a lattice site\n", path, lineno, a[0], a[1], a[2]);
    else if (seen[g]) fprintf(err, "pd_exact: %s:%d: site given twice\n", path, lineno);
    else if (s->n >= nsites) fprintf(err, "pd_exact: %s:%d: more sites than the box holds (%ld)\n", path, lineno, nsites);
    else {
      seen[g] = 1;
      memcpy(s->x + 3 * s->n, a, 3 * sizeof(double));
      s->slot[s->n++] = g;
      memcpy(s->u + 3 * g, a + 3, 3 * sizeof(double));
      memcpy(s->v + 3 * g, a + 6, 3 * sizeof(double));
      continue;
    }
    bad = 1;
  }
  fclose(fp);
  free(seen);
  if (!bad && s->n != nsites) {
    fprintf(err, "pd_exact: %s: %d sites, the box holds %ld\n", path, s->n, nsites);
    bad = 1;
  }
  return bad ? -1 : 0;
}

int exact_write_sites(const char *path, const exact_sites *s, double time, FILE *err)
{
  FILE *fp = fopen(path, "w");
  if (!fp) {
    fprintf(err, "pd_exact: cannot write '%s'\n", path);
    return -1;
  }
  fprintf(fp, "# pd_exact at time %.17g: x y z ux uy uz vx vy vz\n", time);
  for (int i = 0; i < s->n; i++) {
    const double *x = s->x + 3 * i, *u = s->u + 3 * s->slot[i], *v = s->v + 3 * s->slot[i];
    fprintf(fp, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", x[0], x[1], x[2], u[0], u[1],
            u[2], v[0], v[1], v[2]);
  }
  return fclose(fp) ? -1 : 0;
}

void exact_free_sites(exact_sites *s)
{
  free(s->x);
  free(s->slot);
  free(s->u);
  free(s->v);
  memset(s, 0, sizeof(*s));
}
