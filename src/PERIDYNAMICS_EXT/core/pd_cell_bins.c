/* Cell bins (pd_cell_bins.h): a counting sort of points by cell. */
#include "pd_cell_bins.h"

#include "pd_pages.h"

#include <math.h>
#include <string.h>

/* the cell of coordinate x along one dimension, clamped to the grid */
static int cell_of(double x, double lo, double inv, int n)
{
  const double c = floor((x - lo) * inv);
  if (!(c > 0.0)) return 0;
  return c >= (double) n ? n - 1 : (int) c;
}

static int cell_index(const pd_cell_bins *b, const double *p)
{
  const double inv = 1.0 / b->side;
  const int cx = cell_of(p[0], b->lo[0], inv, b->n[0]);
  const int cy = cell_of(p[1], b->lo[1], inv, b->n[1]);
  const int cz = cell_of(p[2], b->lo[2], inv, b->n[2]);
  return (cx * b->n[1] + cy) * b->n[2] + cz;
}

/* The grid over the bounding box; the side grows until the cells number at
 * most max_cells. */
static void size_grid(pd_cell_bins *b, const double hi[3], double side, long max_cells)
{
  for (;;) {
    double cells = 1.0;
    for (int d = 0; d < 3; d++) cells *= floor((hi[d] - b->lo[d]) / side) + 1.0;
    if (cells <= (double) max_cells) break;
    side *= 1.01 * cbrt(cells / (double) max_cells);
  }
  b->side = side;
  for (int d = 0; d < 3; d++) b->n[d] = (int) floor((hi[d] - b->lo[d]) / side) + 1;
}

int pd_cell_bins_build(pd_cell_bins *b, const double *pos, int npoint, double side, long max_cells)
{
  b->start = b->index = NULL;
  b->pos = NULL;
  b->npoint = 0;
  if (!(side > 0.0) || !isfinite(side) || npoint < 0) return -1;
  if (max_cells < 1) max_cells = 1;
  if (max_cells > 0x3fffffffL) max_cells = 0x3fffffffL;
  double hi[3] = {0.0, 0.0, 0.0};
  for (int d = 0; d < 3; d++) b->lo[d] = 0.0;
  for (int i = 0; i < npoint; i++)
    for (int d = 0; d < 3; d++) {
      const double x = pos[3 * i + d];
      if (!isfinite(x)) return -1;
      if (i == 0 || x < b->lo[d]) b->lo[d] = x;
      if (i == 0 || x > hi[d]) hi[d] = x;
    }
  size_grid(b, hi, side, max_cells);
  const int ncells = b->n[0] * b->n[1] * b->n[2];
  /* (pd_pages: large blocks in huge pages, whose first touch is cheaper) */
  b->start = pd_pages_alloc(((size_t) ncells + 1) * sizeof(int));
  b->index = pd_pages_alloc(((size_t) npoint + 1) * sizeof(int));
  b->pos = pd_pages_alloc(((size_t) npoint + 1) * 3 * sizeof(double));
  if (!b->start || !b->index || !b->pos) {
    pd_cell_bins_free(b);
    return -2;
  }
  memset(b->start, 0, ((size_t) ncells + 1) * sizeof(int));
  b->npoint = npoint;
  /* count, then prefix sums give each cell's end; placing the points in
   * reverse input order moves each end back to its start and keeps the
   * input order within a cell */
  for (int i = 0; i < npoint; i++) b->start[cell_index(b, pos + 3 * i) + 1]++;
  for (int c = 0; c < ncells; c++) b->start[c + 1] += b->start[c];
  int *next = b->start + 1;
  for (int i = npoint - 1; i >= 0; i--) {
    const int s = --next[cell_index(b, pos + 3 * i)];
    b->index[s] = i;
    for (int d = 0; d < 3; d++) b->pos[3 * s + d] = pos[3 * i + d];
  }
  /* start[c + 1] is now where cell c begins: shift by one */
  for (int c = 0; c < ncells; c++) b->start[c] = b->start[c + 1];
  b->start[ncells] = npoint;
  return 0;
}

void pd_cell_bins_free(pd_cell_bins *b)
{
  pd_pages_free(b->start);
  pd_pages_free(b->index);
  pd_pages_free(b->pos);
  b->start = b->index = NULL;
  b->pos = NULL;
  b->npoint = 0;
}

/* cells a range of width 2r can span along one dimension */
static int span(const pd_cell_bins *b, double r, int d)
{
  const double cells = floor(2.0 * r / b->side) + 3.0;
  return cells < (double) b->n[d] ? (int) cells : b->n[d];
}

int pd_cell_bins_max_runs(const pd_cell_bins *b, double r)
{
  return span(b, r, 0) * span(b, r, 1);
}

int pd_cell_bins_runs(const pd_cell_bins *b, const double p[3], double r, int axis, double from,
                      int (*runs)[2])
{
  const double inv = 1.0 / b->side;
  int lo[3], hi[3];
  for (int d = 0; d < 3; d++) {
    /* cell_of is monotonic: a point at or above 'from' is in a cell at or
     * above from's */
    const double low = d == axis && from > p[d] - r ? from : p[d] - r;
    lo[d] = cell_of(low, b->lo[d], inv, b->n[d]);
    hi[d] = cell_of(p[d] + r, b->lo[d], inv, b->n[d]);
  }
  /* a column whose cross-section lies farther than r from p (with a margin
   * for the round-off of the cell bounds) holds no point within r */
  const double pad = 1e-6 * b->side, r2 = (r + pad) * (r + pad);
  int nrun = 0;
  for (int cx = lo[0]; cx <= hi[0]; cx++) {
    const double x0 = b->lo[0] + cx * b->side, x1 = x0 + b->side;
    const double dx = p[0] < x0 ? x0 - p[0] : (p[0] > x1 ? p[0] - x1 : 0.0);
    for (int cy = lo[1]; cy <= hi[1]; cy++) {
      const double y0 = b->lo[1] + cy * b->side, y1 = y0 + b->side;
      const double dy = p[1] < y0 ? y0 - p[1] : (p[1] > y1 ? p[1] - y1 : 0.0);
      if (dx * dx + dy * dy > r2) continue;
      const int column = (cx * b->n[1] + cy) * b->n[2];
      const int first = b->start[column + lo[2]], last = b->start[column + hi[2] + 1];
      if (first == last) continue;
      runs[nrun][0] = first;
      runs[nrun][1] = last;
      nrun++;
    }
  }
  return nrun;
}
