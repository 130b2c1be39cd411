/* Each family calibrated on itself (core/pd_calibration.c): the share of a
 * particle's own sums by the completeness of its family, the tolerance of
 * the interior families' scatter, and the blend. */
#include "check.h"
#include "pd_calibration.h"

int main(void)
{
  /* the band [1 - 2 tol, 1 - tol]: own sums above it, complete ones below */
  check_rel("complete family: all its own", pd_calibration_share(1.0, 0.1), 1.0, 0.0);
  check_rel("a jittered family 5% larger: its own", pd_calibration_share(1.05, 0.1), 1.0, 0.0);
  check_rel("at the band's top: its own", pd_calibration_share(0.9, 0.1), 1.0, 1e-12);
  check_rel("mid-band: half its own", pd_calibration_share(0.85, 0.1), 0.5, 1e-12);
  check_rel("at the band's bottom: the complete family's", pd_calibration_share(0.8, 0.1), 0.0, 1e-12);
  check_rel("a flat surface's atom (half its family): the complete family's", pd_calibration_share(0.5, 0.1),
            0.0, 0.0);
  check_rel("no family: the complete family's", pd_calibration_share(0.0, 0.1), 0.0, 0.0);
  check_rel("NaN completeness: the complete family's", pd_calibration_share(NAN, 0.1), 0.0, 0.0);

  /* four robust deviations, within [1e-9, the window] */
  check_rel("tolerance: four deviations", pd_calibration_tolerance(0.03), 0.12, 1e-15);
  check_rel("tolerance of a lattice: round-off", pd_calibration_tolerance(0.0), 1e-9, 0.0);
  check_rel("tolerance at most the window", pd_calibration_tolerance(0.2), PD_CALIBRATION_WINDOW, 0.0);
  /* a lattice atom that lost one bond of 122 (0.8%) takes the complete family */
  check_rel("lattice: one bond lost of 122 -> complete family",
            pd_calibration_share(121.0 / 122.0, pd_calibration_tolerance(0.0)), 0.0, 0.0);

  /* the blend, and round-off snapped to the complete value */
  check_rel("blend: s q + (1 - s) q_complete", pd_calibrated(2.0, 4.0, 0.25), 3.5, 1e-15);
  check_rel("share 1: its own", pd_calibrated(2.0, 4.0, 1.0), 2.0, 0.0);
  check_rel("share 0: the complete value", pd_calibrated(2.0, 4.0, 0.0), 4.0, 0.0);
  const double rounded = 4.0 * (1.0 + 3e-16);
  check_true("own within round-off of complete: exactly the complete value",
             pd_calibrated(rounded, 4.0, 1.0) == 4.0);
  check_true("own 1e-9 away: kept", pd_calibrated(4.0 * (1.0 + 1e-9), 4.0, 1.0) != 4.0);
  return check_summary();
}
