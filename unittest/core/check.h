/* Minimal assertions for the core tests: each check states its tolerance;
 * main() ends with check_summary(), which prints "N passed, N failed".
 * The counters live once, in check.c, so a check made in any file of a
 * test (common.c, model.c, ...) counts toward that test's exit code. */
#ifndef PD_CHECK_H
#define PD_CHECK_H

#include <math.h>
#include <stdio.h>

extern int check_pass_count, check_fail_count;

/* Passes when |got - want| <= tol |want| (tol absolute when want = 0) and
 * got is finite. */
void check_rel(const char *what, double got, double want, double tol);
void check_true(const char *what, int cond);
/* Prints the counts; returns the exit code (0: no check failed). */
int check_summary(void);

#endif
