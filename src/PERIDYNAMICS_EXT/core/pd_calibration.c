#include "pd_calibration.h"

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
