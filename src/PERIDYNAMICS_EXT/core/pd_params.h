/* Engineering constants -> peridynamic constants (3D). */
#ifndef PD_PARAMS_H
#define PD_PARAMS_H

/* PMB micromodulus from the bulk modulus: c = 18 K / (pi delta^4) (MS07 eq. 18). */
double pd_pmb_micromodulus_3d(double bulk, double delta);

/* Peridynamic Lame constants of the ordinary solid in 3D (T14 after eq. 5.3):
 * mu_bar = 5 mu / 2, lambda_bar = lambda - mu. */
typedef struct pd_lame {
  double lambda, mu;
} pd_lame;
pd_lame pd_ordinary_lame_3d(double bulk, double shear);

#endif
