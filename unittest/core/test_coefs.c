/* The declared pair coefficients (pd_coefs.h): the mixing rules, the
 * checks, and every material's table (the LAMMPS side relies on these
 * properties and has no per-coefficient code to catch a slip). */
#include "check.h"
#include "pd_bond_based.h"
#include "pd_coefs.h"
#include "pd_ordinary.h"

#include <string.h>

static void check_table(const char *material, const pd_coef *t, int n)
{
  char what[160];
  snprintf(what, sizeof what, "%s: the horizon comes first, positive, on every line, larger between types",
           material);
  check_true(what, n > 0 && strcmp(t[0].name, "horizon") == 0 && t[0].check == PD_CHECK_POSITIVE &&
                       (t[0].flags & PD_COEF_REQUIRED) && t[0].mix == PD_MIX_MAX);
  for (int k = 0; k < n; k++) {
    int unique = 1;
    for (int l = 0; l < k; l++) unique = unique && strcmp(t[k].name, t[l].name) != 0;
    snprintf(what, sizeof what, "%s: '%s' is declared once", material, t[k].name);
    check_true(what, t[k].name && unique);
    /* a value each type keeps for itself has no place on a line between types */
    snprintf(what, sizeof what, "%s: '%s' mixes by its own type only if refused between types", material,
             t[k].name);
    check_true(what, t[k].mix != PD_MIX_OWN || !(t[k].flags & PD_COEF_PAIR));
    snprintf(what, sizeof what, "%s: '%s' has a range or default it can meet", material, t[k].name);
    check_true(what, (t[k].check != PD_CHECK_RANGE || t[k].lo <= t[k].hi) &&
                         (!(t[k].flags & PD_COEF_DEFAULT) || pd_coef_valid(&t[k], t[k].value)));
    snprintf(what, sizeof what, "%s: '%s' fits a material file key", material, t[k].name);
    check_true(what, strlen(t[k].name) < 32);
  }
}

int main(void)
{
  check_rel("mean of two types (MS07 eq. 30)", pd_coef_mixed(PD_MIX_MEAN, 1.0, 3.0), 2.0, 0.0);
  check_rel("the larger horizon", pd_coef_mixed(PD_MIX_MAX, 1.0, 3.0), 3.0, 0.0);
  check_rel("the smaller critical stretch (MS07 eq. 31)", pd_coef_mixed(PD_MIX_MIN, 1.0, 3.0), 1.0, 0.0);
  check_rel("an infinite critical stretch (no failure) gives the other's", pd_coef_mixed(PD_MIX_MIN, INFINITY, 0.01),
            0.01, 0.0);
  check_true("a type without a value gives the pair none, in either order",
             isnan(pd_coef_mixed(PD_MIX_MAX, NAN, 1.0)) && isnan(pd_coef_mixed(PD_MIX_MAX, 1.0, NAN)) &&
                 isnan(pd_coef_mixed(PD_MIX_MEAN, 1.0, NAN)) && isnan(pd_coef_mixed(PD_MIX_MIN, NAN, 1.0)));
  check_true("own-type and unmixed values give the pair none",
             isnan(pd_coef_mixed(PD_MIX_OWN, 1.0, 1.0)) && isnan(pd_coef_mixed(PD_MIX_NONE, 1.0, 1.0)));

  const pd_coef pos = {"K", "bulk modulus", PD_MIX_MEAN, 0, PD_CHECK_POSITIVE, 0.0, 0.0, 0.0, NULL};
  const pd_coef range = {"m", "strain order", PD_MIX_OWN, 0, PD_CHECK_RANGE, -4.0, 1.0, 0.0, NULL};
  const pd_coef any = {"nu", NULL, PD_MIX_MEAN, 0, PD_CHECK_FINITE, 0.0, 0.0, 0.0, NULL};
  check_true("positive: 0 and below refused", pd_coef_valid(&pos, 1e-300) && !pd_coef_valid(&pos, 0.0) &&
                                                   !pd_coef_valid(&pos, -1.0));
  check_true("range: its ends included, outside refused",
             pd_coef_valid(&range, -4.0) && pd_coef_valid(&range, 1.0) && !pd_coef_valid(&range, 1.0 + 1e-12) &&
                 !pd_coef_valid(&range, -4.5));
  check_true("finite only: any number", pd_coef_valid(&any, -1e300) && pd_coef_valid(&any, 0.0));

  check_table("pd/bond", pd_bond_coefs, PD_BOND_NCOEFS);
  check_table("pd/ordinary", pd_ordinary_coefs, PD_ORD_NCOEFS);
  return check_summary();
}
