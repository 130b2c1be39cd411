/* Classical constitutive laws for the correspondence material (pd/corr).
 * Every law works on a Lagrangian strain tensor of Seth-Hill order m,
 * E = (C^m - 1)/(2m) (E = log(C)/2 at m = 0; the extended correspondence's
 * nonlocal strain, T14 eq. 4.3), and returns the stress T conjugate to it
 * (psi = psi(E), T = d psi / d E) and the energy density it stores. With
 * m = 0 'elastic' is Hencky's hyperelastic solid and the plastic laws are
 * log-strain (Lagrangian) plasticity; with m = 1 'elastic' is the St.
 * Venant-Kirchhoff solid (Green-Lagrange strain). */
#ifndef PD_CORR_LAW_H
#define PD_CORR_LAW_H

typedef enum pd_corr_model {
  PD_CORR_ELASTIC,     /* T = lambda tr(E) 1 + 2 mu E */
  PD_CORR_NEOHOOKEAN,  /* T14 3.2.1: psi = (lambda/2 log J - mu) log J + mu/2 (tr C - 3) */
  PD_CORR_J2,          /* elastic as above on E - E_p, von Mises yield with linear
                          isotropic hardening, radial return (T14 Table 3.1) */
  PD_CORR_JOHNSON_COOK /* J2 with T14's modified Johnson-Cook flow stress (sec. 7.2)
                          times optional thermal softening; optional JC damage */
} pd_corr_model;

typedef struct pd_corr_material {
  pd_corr_model model;
  double lambda, mu;       /* Lame constants (3D material) */
  int plane_stress;        /* E_33 from T_33 = 0 (elastic only) */
  double yield, hardening; /* J2: sigma_y = yield + hardening eps_p;
                              JC: yield is sigma0 */
  /* modified Johnson-Cook flow stress (T14 sec. 7.2):
   * Y = sigma0 (1 + eps_p/eps0)^n (1 + C asinh(rate/(2 rate0))) (1 - T*^mth),
   * eps0 = (sigma0/B)^(1/n); the last factor only with 'thermal' */
  double jc_b, jc_n, jc_c, jc_rate0;
  int thermal;             /* adiabatic heating and thermal softening */
  double t_room, t_melt, t_exp, heat_capacity, taylor_quinney;
  int damage;              /* Johnson-Cook damage: D += d eps_p / eps_f */
  double d[5];             /* eps_f = (d1 + d2 exp(-d3 p/sigma_e))(1 + d4 ln max(rate/rate0, 1))
                              (1 + d5 T*) (T14 sec. 7.2; d5 of Johnson and Cook 1985) */
} pd_corr_material;

/* An atom's history; the laws read and update what they use. */
typedef struct pd_corr_history {
  double plastic[6];   /* plastic strain tensor E_p (J2, JC) */
  double eqps;         /* equivalent plastic strain */
  double temperature;  /* (thermal) */
  double damage;       /* (JC damage) */
  double plastic_work; /* plastic work density dissipated so far */
} pd_corr_history;

/* The increment an atom is in: its history at the increment's start and
 * the strain it was last evaluated at. An evaluation at that strain again
 * (within 1e-12) repeats the increment from its start instead of adding
 * one: LAMMPS evaluates the forces again at unchanged positions when a run
 * starts, and a rate- or temperature-dependent return would flow again. */
typedef struct pd_corr_increment {
  pd_corr_history start;
  double strain[6];
} pd_corr_increment;

/* Begin a new increment at strain E, or go back to the start of the
 * current one when E is the strain it was last evaluated at. */
void pd_corr_increment_enter(pd_corr_increment *inc, const double E[6], pd_corr_history *h);

typedef struct pd_corr_stress {
  double T[6];         /* stress conjugate to E */
  double energy;       /* stored (elastic) energy density */
} pd_corr_stress;

/* Stress of strain E (E[2] is overwritten in plane stress); the plastic laws
 * advance h over a step of length dt (rate effects) of a material of
 * density rho (heating). Returns 0 if the state is not admissible (J <= 0
 * for neo-Hookean, a non-finite stress). */
int pd_corr_law_stress(const pd_corr_material *mat, double m, double E[6], pd_corr_history *h,
                       double dt, double rho, pd_corr_stress *out);

/* The flow stress of a plastic law at equivalent plastic strain eps_p,
 * plastic strain rate and temperature. */
double pd_corr_flow_stress(const pd_corr_material *mat, double eps_p, double rate, double temp);

/* Second Piola-Kirchhoff stress S = 2 d psi/d C from T = d psi/d E, E of
 * order m of C = Q diag(c) Q^T (the derivative of an isotropic tensor
 * function, in C's principal frame). */
void pd_corr_second_pk(double m, const double c[3], const double q[9], const double T[6],
                       double S[6]);

#endif
