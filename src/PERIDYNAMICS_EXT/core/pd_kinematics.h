/* Bond kinematics: stretch, Cauchy-Green scalar, Seth-Hill bond strain. */
#ifndef PD_KINEMATICS_H
#define PD_KINEMATICS_H

/* Bond stretch s = (|Y| - |xi|) / |xi|  (MS07 eq. 14). */
static inline double pd_stretch(double len, double len0) { return (len - len0) / len0; }

/* Cauchy-Green scalar c = |Y|^2 / |xi|^2  (T14 eq. 4.2). */
static inline double pd_cauchy_green(double len, double len0)
{
  const double r = len / len0;
  return r * r;
}

/* Seth-Hill bond strain of order m, eps_m = (c^m - 1) / (2m), m = 0: log(c)/2
 * (T14 eq. 4.2), and its derivative d eps_m / d c = c^(m-1) / 2. */
double pd_seth_hill_strain(double c, double m);
double pd_seth_hill_dstrain(double c, double m);

#endif
