/* Minimal assertions for the core tests: each check states its tolerance;
 * main() ends with check_summary(), which prints "N passed, N failed". */
#ifndef PD_CHECK_H
#define PD_CHECK_H

#include <math.h>
#include <stdio.h>

static int check_pass_count, check_fail_count;

static void check_rel(const char *what, double got, double want, double tol)
{
  const double scale = fabs(want) > 0.0 ? fabs(want) : 1.0;
  const double err = fabs(got - want) / scale;
  const int ok = err <= tol && isfinite(got);
  printf("%s %-58s got %.12g want %.12g (rel err %.2e, tol %.1e)\n", ok ? "PASS" : "FAIL",
         what, got, want, err, tol);
  if (ok) check_pass_count++;
  else check_fail_count++;
}

static void check_true(const char *what, int cond)
{
  printf("%s %s\n", cond ? "PASS" : "FAIL", what);
  if (cond) check_pass_count++;
  else check_fail_count++;
}

static int check_summary(void)
{
  printf("%d passed, %d failed\n", check_pass_count, check_fail_count);
  return check_fail_count ? 1 : 0;
}

#endif
