/* Cell bins (pd_cell_bins.h): every point within a radius is found, once,
 * compared with a brute-force search over all pairs, on a jittered
 * lattice, a random cloud, a plane (2D: one cell along z), two clusters
 * far apart (the cell cap enlarges the cells), coincident points and the
 * empty set. */
#include "check.h"
#include "pd_cell_bins.h"

#include <stdlib.h>

/* a small reproducible generator (the C library's rand differs by platform) */
static double uniform(unsigned long long *s)
{
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double) (*s >> 11) / 9007199254740992.0;
}

static double dist2(const double *a, const double *b)
{
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

/* For every point and radius: the points within r through the runs equal
 * the brute-force set, none seen twice; the runs never exceed the bound;
 * points of a cell keep their input order. The same for the half balls
 * above the point along each axis (the bond build's query): every point
 * within r at or above it is found, and fewer points are scanned. */
static double compare(const char *what, const double *pos, int n, double side, long max_cells)
{
  const double radii[] = {0.0, 0.5, 1.0, 2.7, 3.0001, 5.5};
  pd_cell_bins b;
  check_true(what, pd_cell_bins_build(&b, pos, n, side, max_cells) == 0);
  int *seen = calloc((size_t) n + 1, sizeof(int));
  int ok_sets = 1, ok_once = 1, ok_bound = 1, ok_order = 1, ok_cap = 1, ok_half = 1;
  long scanned_ball = 0, scanned_half = 0;
  const long cells = (long) b.n[0] * b.n[1] * b.n[2];
  if (cells > max_cells || b.start[cells] != n) ok_cap = 0;
  for (long c = 0; c < cells; c++)
    for (int s = b.start[c] + 1; s < b.start[c + 1]; s++)
      if (b.index[s] <= b.index[s - 1]) ok_order = 0;
  for (size_t q = 0; q < sizeof radii / sizeof radii[0]; q++) {
    const double r = radii[q];
    const int maxruns = pd_cell_bins_max_runs(&b, r);
    int (*runs)[2] = malloc(((size_t) maxruns + 1) * sizeof *runs);
    for (int i = 0; i < n; i++)
      for (int axis = -1; axis < 3; axis++) {
        const double from = axis < 0 ? 0.0 : pos[3 * i + axis];
        const int nrun = pd_cell_bins_runs(&b, pos + 3 * i, r, axis, from, runs);
        if (nrun > maxruns) ok_bound = 0;
        int found = 0;
        for (int k = 0; k < nrun; k++)
          for (int s = runs[k][0]; s < runs[k][1]; s++) {
            const int j = b.index[s];
            if (seen[j]++) ok_once = 0;
            if (dist2(b.pos + 3 * s, pos + 3 * i) <= r * r && (axis < 0 || b.pos[3 * s + axis] >= from))
              found++;
            if (axis < 0) scanned_ball++;
            else scanned_half++;
          }
        int want = 0;
        for (int j = 0; j < n; j++) {
          if (dist2(pos + 3 * j, pos + 3 * i) <= r * r && (axis < 0 || pos[3 * j + axis] >= from)) {
            want++;
            if (!seen[j]) *(axis < 0 ? &ok_sets : &ok_half) = 0;
          }
          seen[j] = 0;
        }
        if (found != want) *(axis < 0 ? &ok_sets : &ok_half) = 0;
      }
    free(runs);
  }
  char msg[200];
  snprintf(msg, sizeof msg, "%s: the runs hold every point within r (brute force)", what);
  check_true(msg, ok_sets);
  snprintf(msg, sizeof msg, "%s: the half balls' runs hold every point within r above (brute force)", what);
  check_true(msg, ok_half);
  snprintf(msg, sizeof msg, "%s: the half balls scan no more points (%ld for 3 half balls, %ld for 3 balls)",
           what, scanned_half, 3 * scanned_ball);
  check_true(msg, scanned_half <= 3 * scanned_ball);
  snprintf(msg, sizeof msg, "%s: no point in two runs", what);
  check_true(msg, ok_once);
  snprintf(msg, sizeof msg, "%s: runs within pd_cell_bins_max_runs", what);
  check_true(msg, ok_bound);
  snprintf(msg, sizeof msg, "%s: input order kept within a cell", what);
  check_true(msg, ok_order);
  snprintf(msg, sizeof msg, "%s: at most max_cells cells, all points binned", what);
  check_true(msg, ok_cap);
  free(seen);
  pd_cell_bins_free(&b);
  return scanned_ball ? (double) scanned_half / (3.0 * scanned_ball) : 1.0;
}

int main(void)
{
  unsigned long long seed = 12345;
  enum { L = 9, N = L * L * L };
  double *pos = malloc(3 * N * sizeof(double));

  /* jittered simple cubic lattice, spacing 1, cells of a third of the reach */
  for (int i = 0; i < N; i++) {
    const int ijk[3] = {i % L, (i / L) % L, i / (L * L)};
    for (int d = 0; d < 3; d++) pos[3 * i + d] = ijk[d] + 0.2 * (uniform(&seed) - 0.5);
  }
  /* cells a third of the largest radius, as the bond build's: a half ball
   * scans a little over half of the ball's points (the build's gain) */
  check_true("jittered lattice, side 1: the half balls scan at most 0.6 of the balls' points",
             compare("jittered lattice, side 1", pos, N, 1.0, 1000000) < 0.6);
  compare("jittered lattice, side 3.0001", pos, N, 3.0001, 1000000);
  compare("jittered lattice, side 0.3", pos, N, 0.3, 1000000);

  /* a random cloud in a slab, negative coordinates */
  for (int i = 0; i < N; i++) {
    pos[3 * i] = -4.0 + 12.0 * uniform(&seed);
    pos[3 * i + 1] = -7.0 + 3.0 * uniform(&seed);
    pos[3 * i + 2] = 8.0 * uniform(&seed);
  }
  compare("random cloud", pos, N, 1.5, 1000000);

  /* a plane: every z the same */
  for (int i = 0; i < N; i++) {
    pos[3 * i] = 30.0 * uniform(&seed);
    pos[3 * i + 1] = 25.0 * uniform(&seed);
    pos[3 * i + 2] = 0.25;
  }
  compare("plane (2D)", pos, N, 1.0, 1000000);

  /* two clusters 1e4 apart: capped at 64 cells, the cells grow */
  for (int i = 0; i < N; i++)
    for (int d = 0; d < 3; d++) pos[3 * i + d] = 3.0 * uniform(&seed) + (i % 2 ? 1e4 : 0.0);
  compare("two far clusters, 64 cells", pos, N, 1.0, 64);
  {
    pd_cell_bins b;
    pd_cell_bins_build(&b, pos, N, 1.0, 64);
    check_true("two far clusters: cells grow to meet the cap", b.side > 1.0 && (long) b.n[0] * b.n[1] * b.n[2] <= 64);
    pd_cell_bins_free(&b);
  }

  /* coincident points, and one point, and none */
  for (int i = 0; i < 50; i++)
    for (int d = 0; d < 3; d++) pos[3 * i + d] = (i % 5) * 0.5;
  compare("coincident points", pos, 50, 1.0, 1000);
  compare("one point", pos, 1, 1.0, 1000);
  compare("no points", pos, 0, 1.0, 1000);

  /* bad input */
  pd_cell_bins b;
  pos[4] = NAN;
  check_true("a position that is not finite: -1", pd_cell_bins_build(&b, pos, 3, 1.0, 1000) == -1);
  check_true("side 0: -1", pd_cell_bins_build(&b, pos, 1, 0.0, 1000) == -1);
  free(pos);
  return check_summary();
}
