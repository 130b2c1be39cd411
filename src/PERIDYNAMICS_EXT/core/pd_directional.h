/* Directional correction of a family ('directional_correction yes', the
 * default of pd/bond and pd/ordinary).
 *
 * Under a uniform strain eps a bond of direction n stretches by n.eps.n, so
 * a family's elastic energy is a sum over its bonds of mu (n.eps.n)^2, mu
 * the bond's share of the stiffness (weight x partner volume x |xi|^power:
 * power 1 for a bond-based solid, 0 for the ordinary solid's
 * mu N sum w eps^2 V). The family's constants are those of its fourth moment
 *   M = sum mu n (x) n (x) n (x) n,
 * which a continuum family has isotropic. A lattice family does not (the
 * square lattice's shear at 45 degrees against along the rows), nor does an
 * irregular one, and no scalar normalization can fix that. Here each bond
 * weight is multiplied by a quartic form of the bond's direction,
 *   f(n) = sum_A c_A n^A   (A the monomials of degree 4: 15 in 3D, 5 in 2D),
 * fitted per family so that sum mu f(n) n (x) n (x) n (x) n is the isotropic
 * tensor t (I I + 2 sym) of the same trace (t = trace / 15 in 3D, / 8 in
 * 2D). The trace is kept (sum mu f = sum mu): the normalizations and
 * calibrations built on it are unchanged, and a family that is already
 * isotropic (the hexagonal lattice) gets f = 1. The quartic forms are as
 * many as the conditions, so the fit is a square linear system whose
 * matrix is the family's eighth moments (positive definite when the bond
 * directions are not all on a few lines). */
#ifndef PD_DIRECTIONAL_H
#define PD_DIRECTIONAL_H

/* Monomials of degree 4 in 3D and the moments a fit needs: the trace
 * sum mu, then the eighth moments sum mu n^B (45 in 3D, 9 in 2D). */
#define PD_DIRECTIONAL_MAX_TERMS 15
#define PD_DIRECTIONAL_MAX_MOMENTS 46

/* The quartic form's coefficients (15 in 3D, 5 in 2D). */
int pd_directional_terms(int dim);
/* The per-family sums of a fit (46 in 3D, 10 in 2D). */
int pd_directional_moments(int dim);

/* Adds one bond (unit direction n, stiffness share mu) to a family's sums. */
void pd_directional_add(int dim, const double n[3], double mu, double *moments);
/* The same in two steps, for a bond added to both its ends' sums: the
 * eighth-degree monomials n^B of its direction (45 in 3D, 9 in 2D), then
 * their sums' update; pd_directional_add does exactly these operations. */
void pd_directional_monomials(int dim, const double n[3], double *m);
void pd_directional_accumulate(int dim, const double *m, double mu, double *moments);

/* Numbers of a direction, (a.n)^8 for two fixed directions a with
 * unrelated irrational components: two families whose sums of mu and of
 * mu times each agree to round-off have the same eighth moments, short of
 * a coincidence, and so fit the same form. */
#define PD_DIRECTIONAL_SIGNATURES 2
void pd_directional_signatures(const double n[3], double s[PD_DIRECTIONAL_SIGNATURES]);
/* The quartic form of a family from its sums. Returns 0, or -1 when the
 * eighth moments are singular (a family too small or flat to fit: form is
 * then the isotropic one, f = 1). */
int pd_directional_fit(int dim, const double *moments, double *form);

/* f = 1 as a quartic form: (n.n)^2. */
void pd_directional_unit(int dim, double *form);

/* The smallest factor a form may give a bond of its own family: a family
 * too irregular for a quartic fit (a few bonds, an influence that vanishes
 * at the horizon) can ask for a negative stiffness. */
#define PD_DIRECTIONAL_FLOOR 0.25

/* A form whose smallest factor on its own family's bonds is 'smallest',
 * limited to PD_DIRECTIONAL_FLOOR: moved toward f = 1 just enough, form =
 * a form + (1 - a) (n.n)^2. Returns 1 if it was limited, 0 if not. */
int pd_directional_limit(int dim, double *form, double smallest);

/* The factor f(n) of a bond direction (unit n). */
double pd_directional_factor(int dim, const double *form, const double n[3]);

/* The factors of two forms (a bond's two ends) at one direction, in f[0]
 * and f[1]: each form's the same numbers as alone (pd_directional_factor
 * is the first of them), their two chains of adds side by side (one
 * form's chain of adds was the time of a factor). */
void pd_directional_factors(int dim, const double *form_a, const double *form_b, const double n[3],
                            double f[2]);

/* The form of a complete lattice family (pd_lattice.h), stiffness share
 * w V |xi|^power: what every interior atom of the lattice fits. Returns
 * pd_directional_fit's answer. */
struct pd_family;
int pd_family_directional_form(const struct pd_family *f, int power, double *form);

#endif
