#include "pd_params.h"

#include "pd_macros.h"

#include <math.h>

static int complete(pd_elastic *o)
{
  if (!(o->K > 0.0) || !(o->G > 0.0) || !(o->nu > -1.0) || !(o->nu < 0.5)) return -1;
  return 0;
}

int pd_elastic_from_E_nu(double E, double nu, pd_elastic *out)
{
  out->E = E;
  out->nu = nu;
  out->K = E / (3.0 * (1.0 - 2.0 * nu));
  out->G = E / (2.0 * (1.0 + nu));
  if (!(E > 0.0) || !(nu > -1.0) || !(nu < 0.5)) return -1;
  return complete(out);
}

int pd_elastic_from_K_G(double K, double G, pd_elastic *out)
{
  out->K = K;
  out->G = G;
  out->E = 9.0 * K * G / (3.0 * K + G);
  out->nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
  return complete(out);
}

int pd_dimension_count(pd_dimension dim)
{
  return dim == PD_3D ? 3 : 2;
}

double pd_pmb_poisson(pd_dimension dim)
{
  return dim == PD_PLANE_STRESS ? 1.0 / 3.0 : 0.25;
}

double pd_pmb_micromodulus(pd_dimension dim, double E, double delta, double thickness)
{
  const double d3 = delta * delta * delta;
  switch (dim) {
  case PD_PLANE_STRESS: return 9.0 * E / (PD_PI * d3 * thickness);
  case PD_PLANE_STRAIN: return 48.0 * E / (5.0 * PD_PI * d3 * thickness);
  default: return 12.0 * E / (PD_PI * d3 * delta);
  }
}

double pd_pmb_micromodulus_3d(double bulk, double delta)
{
  return 18.0 * bulk / (PD_PI * delta * delta * delta * delta);
}

double pd_pmb_moment_continuum(int dim, double delta, double thickness)
{
  const double d3 = delta * delta * delta;
  return dim == 3 ? PD_PI * d3 * delta : 2.0 * PD_PI * d3 * thickness / 3.0;
}

pd_lame pd_ordinary_lame(pd_dimension dim, const pd_elastic *m)
{
  const double mu = m->G;
  const double lambda = m->K - 2.0 * mu / 3.0;
  pd_lame l;
  switch (dim) {
  case PD_PLANE_STRESS:
    l.lambda = m->E * m->nu / (1.0 - m->nu * m->nu) - mu;
    l.mu = 2.0 * mu;
    break;
  case PD_PLANE_STRAIN:
    l.lambda = lambda - mu;
    l.mu = 2.0 * mu;
    break;
  default:
    l.lambda = lambda - mu;
    l.mu = 2.5 * mu;
  }
  return l;
}

pd_lame pd_ordinary_lame_3d(double bulk, double shear)
{
  pd_elastic m;
  pd_elastic_from_K_G(bulk, shear, &m);
  return pd_ordinary_lame(PD_3D, &m);
}

double pd_longitudinal_speed(pd_dimension dim, const pd_elastic *m, double rho)
{
  const double modulus = dim == PD_PLANE_STRESS ? m->E / (1.0 - m->nu * m->nu)
                                                : m->K + 4.0 * m->G / 3.0;
  return sqrt(modulus / rho);
}
