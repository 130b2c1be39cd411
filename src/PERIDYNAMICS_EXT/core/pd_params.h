/* Engineering constants -> peridynamic constants, for 3D and for 2D plane
 * stress or plane strain. Elastic constants are always those of the 3D
 * material (E, nu or K, G); 2D models take the plate thickness. */
#ifndef PD_PARAMS_H
#define PD_PARAMS_H

typedef enum pd_dimension { PD_3D, PD_PLANE_STRESS, PD_PLANE_STRAIN } pd_dimension;

typedef struct pd_elastic {
  double E, nu, K, G;
} pd_elastic;

/* Complete a set from (E, nu) or from (K, G); 0 on success, -1 if the
 * result is not a stable isotropic material (K <= 0, G <= 0, nu not in (-1, 1/2)). */
int pd_elastic_from_E_nu(double E, double nu, pd_elastic *out);
int pd_elastic_from_K_G(double K, double G, pd_elastic *out);

/* Spatial dimension of the model: 2 or 3. */
int pd_dimension_count(pd_dimension dim);

/* Poisson's ratio that bond-based (PMB) elasticity can represent:
 * 1/4 in 3D and plane strain, 1/3 in plane stress. */
double pd_pmb_poisson(pd_dimension dim);

/* PMB micromodulus per unit volume of partner (MS07 eq. 18 and its 2D
 * analogues): 3D 18 K / (pi delta^4) = 12 E / (pi delta^4) at nu = 1/4;
 * plane stress 9 E / (pi delta^3 t); plane strain 48 E / (5 pi delta^3 t). */
double pd_pmb_micromodulus(pd_dimension dim, double E, double delta, double thickness);
double pd_pmb_micromodulus_3d(double bulk, double delta);

/* The continuum family's moment that those micromoduli assume, the integral
 * of |xi| over the horizon (times t in 2D): 3D pi delta^4, 2D 2 pi delta^3 t / 3.
 * A family's own moment sum w V |xi| (pd_family_moment of power 1) in its
 * place calibrates c on that family: c_family = c M_continuum / M_family
 * gives a uniform dilatation the classical energy at its atom. */
double pd_pmb_moment_continuum(int dim, double delta, double thickness);

/* Peridynamic Lame constants of the ordinary solid (T14 eq. 5.1-5.3):
 * 3D mu_bar = 5 mu / 2, lambda_bar = lambda - mu; 2D mu_bar = 2 mu,
 * lambda_bar = lambda_2D - mu, lambda_2D = E nu / (1 - nu^2) in plane
 * stress and the 3D lambda in plane strain. */
typedef struct pd_lame {
  double lambda, mu;
} pd_lame;
pd_lame pd_ordinary_lame(pd_dimension dim, const pd_elastic *m);
pd_lame pd_ordinary_lame_3d(double bulk, double shear);

/* Classical longitudinal (P) wave speed of the model: sqrt(M / rho), with
 * M = lambda + 2 mu (3D, plane strain) or E / (1 - nu^2) (plane stress). */
double pd_longitudinal_speed(pd_dimension dim, const pd_elastic *m, double rho);

#endif
