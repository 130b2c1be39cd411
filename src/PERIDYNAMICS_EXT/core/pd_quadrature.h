/* Partial-volume quadrature (Seleson 2014, exact intersection areas, cell
 * centres kept as quadrature points): the share of a neighbour's cell that
 * lies inside the horizon. The cell is an axis-aligned square (2D) or cube
 * (3D) of side a centred on the neighbour's reference position; the
 * horizon is a disk or ball of radius delta centred on the owner. */
#ifndef PD_QUADRATURE_H
#define PD_QUADRATURE_H

/* Area of the rectangle [x0, x1] x [y0, y1] inside the disk of radius rho
 * centred at the origin; exact up to round-off (piecewise primitives of the
 * circle between the points where its edges cut the rectangle's sides). */
double pd_rect_disk_area(double x0, double x1, double y0, double y1, double rho);

/* Fraction (0 .. 1) of the square of side a centred at c[0..1] inside the
 * disk of radius delta centred at the origin: exact up to round-off. */
double pd_cell_fraction_2d(const double c[2], double a, double delta);

/* The same for the cube of side a centred at c[0..2] and the ball: the
 * exact slice areas integrated over z, the integral broken at every kink of
 * the slice area (where the circle passes an edge line or a corner of the
 * slice) and each piece integrated by Gauss-Legendre after z = p + (q - p)
 * sin^2(t), which smooths the square-root behaviour at the kinks: about
 * 1e-13 of a^3. */
double pd_cell_fraction_3d(const double c[3], double a, double delta);

/* pd_cell_fraction_2d or _3d by dim (2 or 3); c has dim components. */
double pd_cell_fraction(int dim, const double *c, double a, double delta);

/* How far beyond the horizon a bond with a cell of side a can reach and
 * still have a share inside: a sqrt(dim) / 2 (half the cell's diagonal). */
double pd_cell_reach(int dim, double a);

#endif
