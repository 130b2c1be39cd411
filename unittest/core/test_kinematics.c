/* Seth-Hill bond strain (T14 eq. 4.2) and the influence functions. */
#include "check.h"
#include "pd_influence.h"
#include "pd_kinematics.h"
#include "pd_macros.h"
#include "pd_seth_hill.h"

int main(void)
{
  const double c = 1.21; /* |Y| / |xi| = 1.1 */
  /* m = 1/2 is the stretch, m = 1 the Green-Lagrange strain, m = 0 the log. */
  check_rel("eps_1/2 equals the stretch", pd_seth_hill_strain(c, 0.5), 0.1, 1e-14);
  check_rel("eps_1 equals (c - 1)/2", pd_seth_hill_strain(c, 1.0), 0.105, 1e-14);
  check_rel("eps_0 equals log(c)/2", pd_seth_hill_strain(c, 0.0), 0.5 * log(c), 1e-15);
  /* Continuity in m across the series branch (|m| < 1e-8): the error of the
   * two-term series is O(m^2 log^3 c), far below 1e-12. */
  check_rel("eps_m continuous at m = 1e-8", pd_seth_hill_strain(c, 1.0000001e-8),
            pd_seth_hill_strain(c, 0.9999999e-8), 1e-12);
  /* Derivative against central differences (step 1e-6: error ~1e-12). */
  const double orders[] = {-1.0, 0.0, 0.5, 2.0};
  for (int k = 0; k < 4; k++) {
    const double m = orders[k], h = 1e-6;
    const double fd = (pd_seth_hill_strain(c + h, m) - pd_seth_hill_strain(c - h, m)) / (2 * h);
    char what[64];
    snprintf(what, sizeof what, "d eps/dc = c^(m-1)/2 for m = %g", m);
    check_rel(what, pd_seth_hill_dstrain(c, m), fd, 1e-9);
  }
  /* Tupek's polynomials integrate to the dimension over the horizon
   * (T14 eq. 6.6, 6.7); midpoint rule with 1e5 cells: error ~1e-10. */
  const double delta = 0.7;
  double s2 = 0.0, s3 = 0.0;
  const int n = 100000;
  for (int k = 0; k < n; k++) {
    const double r = (k + 0.5) * delta / n;
    s2 += 2 * PD_PI * r * pd_influence(PD_INFLUENCE_TUPEK, 2, r, delta) * delta / n;
    s3 += 4 * PD_PI * r * r * pd_influence(PD_INFLUENCE_TUPEK, 3, r, delta) * delta / n;
  }
  check_rel("2D Tupek influence integrates to 2", s2, 2.0, 1e-8);
  check_rel("3D Tupek influence integrates to 3", s3, 3.0, 1e-8);
  check_true("influence vanishes beyond the horizon",
             pd_influence(PD_INFLUENCE_CONSTANT, 3, 1.0001 * delta, delta) == 0.0);
  check_true("influence names round-trip",
             pd_influence_from_name(pd_influence_name(PD_INFLUENCE_GAUSS)) == PD_INFLUENCE_GAUSS &&
                 pd_influence_from_name("nonsense") == -1);
  /* Legacy partial volume: 1 well inside, 1/2 at the horizon, 0 at delta + lc/2. */
  check_rel("legacy partial volume at the horizon", pd_partial_volume_legacy(1.0, 1.0, 0.2), 0.5, 1e-14);
  check_rel("legacy partial volume inside", pd_partial_volume_legacy(0.5, 1.0, 0.2), 1.0, 0);
  /* The bond loop's one reciprocal per bond, q = 1/(|xi| |Y|): the stretch
   * and the force per length taken from it agree with the direct quotients
   * to a few ulps (tolerance 4e-16 relative: q and |Y| q round twice), for
   * stretched, compressed and unstretched bonds. */
  const double lens[] = {1.3, 0.7, 1.0 + 1e-9, 1.0};
  for (int k = 0; k < 4; k++) {
    pd_bond bd = {0};
    bd.r0 = 0.37;
    bd.len = lens[k] * bd.r0;
    char what[96];
    const double want = (bd.len - bd.r0) / bd.r0;
    snprintf(what, sizeof what, "stretch through q at |Y|/|xi| = %.10g", lens[k]);
    if (want == 0.0) check_true(what, pd_bond_stretch(&bd) == 0.0);
    else check_rel(what, pd_bond_stretch(&bd), want, 4e-16 * fabs(1.0 / want));
    snprintf(what, sizeof what, "m = 1/2 rate per length is 1/(|xi| |Y|) at %.10g", lens[k]);
    check_rel(what, pd_bond_strain_rate_per_length(PD_ORDER_HALF, 0.5, want, &bd),
              1.0 / (bd.r0 * bd.len), 0.0);
    const double m = -1.0, eps = pd_bond_strain(PD_ORDER_ANY, m, &bd);
    snprintf(what, sizeof what, "m = -1 rate per length x |Y| is the rate at %.10g", lens[k]);
    check_rel(what, pd_bond_strain_rate_per_length(PD_ORDER_ANY, m, eps, &bd) * bd.len,
              pd_bond_strain_rate(PD_ORDER_ANY, m, eps, &bd), 4e-16);
  }
  /* Coincident ends: no force (no direction), the stretch -1. */
  pd_bond zero = {0};
  zero.r0 = 0.37;
  check_true("zero length: q = 0, stretch -1, no force per length for any order",
             pd_bond_inverse(&zero) == 0.0 && pd_bond_stretch(&zero) == -1.0 &&
                 pd_per_length(5.0, &zero) == 0.0 &&
                 pd_bond_strain_rate_per_length(PD_ORDER_HALF, 0.5, -1.0, &zero) == 0.0 &&
                 pd_bond_strain_rate_per_length(PD_ORDER_LOG, 0.0, 0.0, &zero) == 0.0);
  return check_summary();
}
