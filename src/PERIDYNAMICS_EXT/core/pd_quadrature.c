#include "pd_quadrature.h"

#include "pd_macros.h"

#include <math.h>

/* int_0^x sqrt(rho^2 - t^2) dt for |x| <= rho */
static double circle_primitive(double x, double rho)
{
  const double s = fmax(-1.0, fmin(1.0, x / rho));
  const double h = sqrt(fmax(rho * rho - x * x, 0.0));
  return 0.5 * (x * h + rho * rho * asin(s));
}

static void sort_small(double *v, int n)
{
  for (int i = 1; i < n; i++)
    for (int k = i; k > 0 && v[k - 1] > v[k]; k--) {
      const double t = v[k];
      v[k] = v[k - 1];
      v[k - 1] = t;
    }
}

/* A = int over x of the length of [y0, y1] inside [-h(x), h(x)],
 * h = sqrt(rho^2 - x^2). Between the x where h meets |y0| or |y1| each
 * bound is either the constant y or +-h, integrated exactly. */
double pd_rect_disk_area(double x0, double x1, double y0, double y1, double rho)
{
  if (!(rho > 0.0)) return 0.0;
  const double a = fmax(x0, -rho), b = fmin(x1, rho);
  if (a >= b || y0 >= rho || y1 <= -rho || y0 >= y1) return 0.0;
  double pts[6];
  int n = 0;
  pts[n++] = a;
  const double ys[2] = {y0, y1};
  for (int k = 0; k < 2; k++)
    if (fabs(ys[k]) < rho) {
      const double q = sqrt(rho * rho - ys[k] * ys[k]);
      if (-q > a && -q < b) pts[n++] = -q;
      if (q > a && q < b) pts[n++] = q;
    }
  pts[n++] = b;
  sort_small(pts, n);
  double area = 0.0;
  for (int k = 0; k + 1 < n; k++) {
    const double p = pts[k], q = pts[k + 1];
    if (!(q > p)) continue;
    const double m = 0.5 * (p + q), hm = sqrt(fmax(rho * rho - m * m, 0.0));
    if (fmin(y1, hm) <= fmax(y0, -hm)) continue;    /* the strip misses the disk here */
    const double arc = circle_primitive(q, rho) - circle_primitive(p, rho);
    const double top = y1 < hm ? y1 * (q - p) : arc;
    const double bottom = y0 > -hm ? y0 * (q - p) : -arc;
    area += top - bottom;
  }
  return area;
}

/* 0: the cell is outside the horizon, 1: inside, -1: cut. */
static int cell_side(int dim, const double *ac, double h, double delta)
{
  double near2 = 0.0, far2 = 0.0;
  for (int d = 0; d < dim; d++) {
    const double n = fmax(ac[d] - h, 0.0), f = ac[d] + h;
    near2 += n * n;
    far2 += f * f;
  }
  if (near2 >= delta * delta) return 0;
  if (far2 <= delta * delta) return 1;
  return -1;
}

double pd_cell_fraction_2d(const double c[2], double a, double delta)
{
  const double h = 0.5 * a;
  const double ac[2] = {fabs(c[0]), fabs(c[1])};
  const int side = cell_side(2, ac, h, delta);
  if (side >= 0) return side;
  const double f = pd_rect_disk_area(ac[0] - h, ac[0] + h, ac[1] - h, ac[1] + h, delta) / (a * a);
  return fmin(1.0, fmax(0.0, f));
}

/* Gauss-Legendre, 16 points: the positive nodes of [-1, 1] and weights */
enum { GL_HALF = 8 };
static const double GL_X[GL_HALF] = {0.989400934991649932596, 0.944575023073232576078,
                                     0.865631202387831743880, 0.755404408355003033895,
                                     0.617876244402643748447, 0.458016777657227386342,
                                     0.281603550779258913230, 0.0950125098376374401853};
static const double GL_W[GL_HALF] = {0.0271524594117540948518, 0.0622535239386478928628,
                                     0.0951585116824927848099, 0.124628971255533872052,
                                     0.149595988816576732082, 0.169156519395002538189,
                                     0.182603415044923588867, 0.189450610455068496285};

/* int_p^q A(z) dz, z = p + (q - p) sin^2 t, t in [0, pi/2] */
static double slab(const double lo[2], const double hi[2], double delta, double p, double q)
{
  const double half = 0.25 * PD_PI;
  double sum = 0.0;
  for (int k = 0; k < GL_HALF; k++)
    for (int s = -1; s <= 1; s += 2) {
      const double t = half * (1.0 + s * GL_X[k]);
      const double st = sin(t), z = p + (q - p) * st * st;
      const double rho = sqrt(fmax(delta * delta - z * z, 0.0));
      const double jac = (q - p) * sin(2.0 * t);
      sum += GL_W[k] * jac * pd_rect_disk_area(lo[0], hi[0], lo[1], hi[1], rho);
    }
  return half * sum;
}

double pd_cell_fraction_3d(const double c[3], double a, double delta)
{
  const double h = 0.5 * a;
  /* by symmetry, the cell in the positive octant of its centre */
  const double ac[3] = {fabs(c[0]), fabs(c[1]), fabs(c[2])};
  const int side = cell_side(3, ac, h, delta);
  if (side >= 0) return side;
  const double d2 = delta * delta;
  const double lo[2] = {ac[0] - h, ac[1] - h}, hi[2] = {ac[0] + h, ac[1] + h};
  const double z0 = fmax(ac[2] - h, -delta), z1 = fmin(ac[2] + h, delta);
  /* the kinks: z where rho^2 = delta^2 - z^2 equals x^2, y^2 or x^2 + y^2
   * of an edge line or corner of the slice */
  double pts[2 + 2 * 8];
  int n = 0;
  pts[n++] = z0;
  pts[n++] = z1;
  const double s[8] = {lo[0] * lo[0], hi[0] * hi[0], lo[1] * lo[1], hi[1] * hi[1],
                       lo[0] * lo[0] + lo[1] * lo[1], lo[0] * lo[0] + hi[1] * hi[1],
                       hi[0] * hi[0] + lo[1] * lo[1], hi[0] * hi[0] + hi[1] * hi[1]};
  for (int k = 0; k < 8; k++)
    if (s[k] < d2) {
      const double z = sqrt(d2 - s[k]);
      if (z > z0 && z < z1) pts[n++] = z;
      if (-z > z0 && -z < z1) pts[n++] = -z;
    }
  sort_small(pts, n);
  double vol = 0.0;
  for (int k = 0; k + 1 < n; k++)
    if (pts[k + 1] > pts[k]) vol += slab(lo, hi, delta, pts[k], pts[k + 1]);
  return fmin(1.0, fmax(0.0, vol / (a * a * a)));
}

double pd_cell_fraction(int dim, const double *c, double a, double delta)
{
  return dim == 2 ? pd_cell_fraction_2d(c, a, delta) : pd_cell_fraction_3d(c, a, delta);
}

double pd_cell_reach(int dim, double a)
{
  return 0.5 * a * sqrt((double) dim);
}
