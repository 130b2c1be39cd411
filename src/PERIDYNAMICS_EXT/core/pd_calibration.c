#include "pd_calibration.h"

#include "pd_bond_loop.h"

#include <math.h>

double pd_calibration_share(double completeness, double tolerance)
{
  if (!(completeness > 0.0)) return 0.0;
  if (!(tolerance > 0.0)) return completeness >= 1.0 ? 1.0 : 0.0;
  const double s = (completeness - (1.0 - 2.0 * tolerance)) / tolerance;
  return s >= 1.0 ? 1.0 : (s <= 0.0 ? 0.0 : s);
}

double pd_calibrated(double own, double complete, double share)
{
  if (fabs(own - complete) <= 1e-12 * fabs(complete)) return complete;
  if (share >= 1.0) return own;
  if (share <= 0.0) return complete;
  return share * own + (1.0 - share) * complete;
}

double pd_calibration_tolerance(double scatter)
{
  const double tol = 4.0 * scatter;
  if (!(tol > 1e-9)) return 1e-9;
  return tol > PD_CALIBRATION_WINDOW ? PD_CALIBRATION_WINDOW : tol;
}

/* w |xi|^power at both ends */
static void moment_value(const void *ctx, const pd_bond *bd, double *a, double *b)
{
  const int power = *(const int *) ctx;
  double r = 1.0;
  for (int k = 0; k < (power < 0 ? -power : power); k++) r *= bd->r0;
  *a = *b = power < 0 ? bd->w / r : bd->w * r;
}

void pd_family_moment(const pd_bond_view *b, const double *vol, int power, double *moment)
{
  pd_reference_sums(b, NULL, 0, vol, moment, &power, moment_value, 0);
}
