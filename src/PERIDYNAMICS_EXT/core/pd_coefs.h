/* Declared pair coefficients. Each material lists the pair_coeff keywords
 * it takes in a table next to its physics (pd_bond_based.c, pd_ordinary.c);
 * each failure law lists its own (on the LAMMPS side, with its parsing).
 * An entry says how bonds between two types get a value, on which lines
 * and from where it may come, and what a given value must satisfy. The
 * LAMMPS glue reads the tables: parsing, checks, mixing, material files and
 * restart have no per-coefficient code. */
#ifndef PD_COEFS_H
#define PD_COEFS_H

/* How bonds between two types I != J get a value when no pair_coeff I J
 * line gives one. A type without a value (NaN) gives the pair none. */
typedef enum pd_coef_mix {
  PD_MIX_MEAN, /* the mean of the two types' values (MS07 eq. 30) */
  PD_MIX_MAX,  /* the larger (the horizon) */
  PD_MIX_MIN,  /* the smaller (the critical stretch, MS07 eq. 31) */
  PD_MIX_OWN,  /* none between types: each atom uses its own type's value,
                  given on its own line (pair_coeff I I) only */
  PD_MIX_NONE  /* no rule: a pair of types with values needs its own
                  pair_coeff I J line */
} pd_coef_mix;

/* What a given value must satisfy. Every value is a finite number
 * (checked when it is read); these are on top. */
typedef enum pd_coef_check {
  PD_CHECK_FINITE,   /* nothing more */
  PD_CHECK_POSITIVE, /* > 0 */
  PD_CHECK_RANGE     /* lo <= value <= hi */
} pd_coef_check;

/* Where a coefficient may be given (pd_coef.flags). */
enum {
  PD_COEF_PAIR = 1,     /* on a pair_coeff I J line with I != J */
  PD_COEF_FILE = 2,     /* from a material file (pair_coeff * * file) */
  PD_COEF_REQUIRED = 4, /* on every line ('nobond' aside) */
  PD_COEF_DEFAULT = 8   /* not given: 'value' (where it may be given) */
};

typedef struct pd_coef {
  const char *name;    /* pair_coeff keyword, material-file key */
  const char *what;    /* what it is, for messages ("bulk modulus"), or NULL */
  pd_coef_mix mix;
  int flags;           /* PD_COEF_* */
  pd_coef_check check;
  double lo, hi;       /* PD_CHECK_RANGE */
  double value;        /* PD_COEF_DEFAULT */
  /* the name a failure law reads it under, if not 'name' (legacy PERI's
   * s00 is kept as s0), or NULL */
  const char *label;
} pd_coef;

/* The horizon, every material's first coefficient: the larger of the two
 * types' between them, given on every line. */
#define PD_COEF_HORIZON \
  {"horizon", NULL, PD_MIX_MAX, PD_COEF_PAIR | PD_COEF_FILE | PD_COEF_REQUIRED, PD_CHECK_POSITIVE, 0.0, 0.0, 0.0, NULL}

/* 1 if a (finite) value satisfies the entry's check. */
int pd_coef_valid(const pd_coef *c, double v);

/* The value of bonds between two types from theirs (a, b) by the rule:
 * NaN when either has none, for PD_MIX_OWN and for PD_MIX_NONE. */
double pd_coef_mixed(pd_coef_mix mix, double a, double b);

#endif
