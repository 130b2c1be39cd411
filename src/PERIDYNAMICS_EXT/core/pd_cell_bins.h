/* Cell bins: points sorted into cubic cells, to find every point within a
 * radius of a given one without a neighbor list (the bond families are
 * built this way, once, from the reference positions).
 *
 * Cells are numbered with z fastest, so a column of cells along z holds
 * one contiguous run of the sorted points: a query is a few runs (one per
 * column that can reach the query ball), which the caller scans with its
 * own distance test. Within a cell the points keep their input order, so
 * the runs, and what a caller builds from them, do not depend on anything
 * but the input. Allocation happens once, in pd_cell_bins_build. */
#ifndef PD_CELL_BINS_H
#define PD_CELL_BINS_H

typedef struct pd_cell_bins {
  int n[3];       /* cells per dimension */
  double lo[3];   /* lower corner of cell (0, 0, 0) */
  double side;    /* cell side */
  int npoint;
  int *start;     /* n[0] n[1] n[2] + 1 entries: first sorted point of each cell */
  int *index;     /* npoint: the input index of each sorted point */
  double *pos;    /* 3 npoint: the sorted points' positions */
} pd_cell_bins;

/* Bins npoint points (pos: x, y, z of each) into cells of at least 'side'
 * (larger if the points' bounding box would need more than max_cells
 * cells). Returns 0, -1 if a position is not finite or side is not
 * positive, -2 if memory ran out; on failure b holds nothing to free. */
int pd_cell_bins_build(pd_cell_bins *b, const double *pos, int npoint, double side, long max_cells);

void pd_cell_bins_free(pd_cell_bins *b);

/* The most runs a query of radius r can give (size of the runs array). */
int pd_cell_bins_max_runs(const pd_cell_bins *b, double r);

/* The runs of sorted points in the cells that a ball of radius r around p
 * can touch: run q is sorted points runs[q][0] <= s < runs[q][1]. Every
 * point within r of p is in a run (points farther away may be too).
 * axis 0, 1 or 2 asks only for the points whose coordinate along it is at
 * least 'from' (the cells wholly below are left out: the bond build asks
 * for the partners above an atom); -1 for the whole ball. Returns the
 * number of runs (at most pd_cell_bins_max_runs(b, r)). */
int pd_cell_bins_runs(const pd_cell_bins *b, const double p[3], double r, int axis, double from,
                      int (*runs)[2]);

#endif
