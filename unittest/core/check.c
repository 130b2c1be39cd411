#include "check.h"

int check_pass_count, check_fail_count;

static void count(int ok)
{
  if (ok) check_pass_count++;
  else check_fail_count++;
}

void check_rel(const char *what, double got, double want, double tol)
{
  const double scale = fabs(want) > 0.0 ? fabs(want) : 1.0;
  const double err = fabs(got - want) / scale;
  const int ok = err <= tol && isfinite(got);
  printf("%s %-58s got %.12g want %.12g (rel err %.2e, tol %.1e)\n", ok ? "PASS" : "FAIL",
         what, got, want, err, tol);
  count(ok);
}

void check_true(const char *what, int cond)
{
  printf("%s %s\n", cond ? "PASS" : "FAIL", what);
  count(cond);
}

int check_summary(void)
{
  printf("%d passed, %d failed\n", check_pass_count, check_fail_count);
  return check_fail_count ? 1 : 0;
}
