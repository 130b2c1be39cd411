/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: what every failure law shares on the LAMMPS side, and
   the registry: one law of each row of core/pd_laws.h per pair style.
------------------------------------------------------------------------- */

#include "pd_failure_law.h"

#include "error.h"
#include "fix_pd_bonds.h"
#include "pair_pd.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

std::vector<std::unique_ptr<PDFailureLaw>> LAMMPS_NS::pd_failure_laws(PairPD *pair)
{
  std::vector<std::unique_ptr<PDFailureLaw>> laws;
#define PD_LAW_MAKE(ID, name, ...) laws.emplace_back(pd_make_law_##name(pair, PD_FAIL_##ID));
  PD_FAILURE_LAWS(PD_LAW_MAKE, ~)
#undef PD_LAW_MAKE
  return laws;
}

PDFailureLaw::PDFailureLaw(PairPD *pair, pd_fail_law id, const char *name, const pd_coef *coefs,
                           int ncoefs) :
    Pointers(pair->lmp), id(id), name(name), coefs(coefs, coefs + ncoefs), pair(pair)
{
}

bool PDFailureLaw::declares(int col) const
{
  return entry(col) != nullptr;
}

const pd_coef *PDFailureLaw::entry(int col) const
{
  for (size_t k = 0; k < cols.size(); k++)
    if (cols[k] == col) return &coefs[k];
  return nullptr;
}

// A material file's values of other laws' coefficients are not this law's
// business: the file describes the material, the line chose the law.
void PDFailureLaw::settle(PDCoefLine &line) const
{
  for (size_t p = fail_column() + 1; p < line.values.size(); p++)
    if (!line.seen[p] && !declares(p)) line.values[p] = NAN;
}

double &PDFailureLaw::value(int k, int i, int j)
{
  return pair->coef[cols[k]][i][j];
}

bool PDFailureLaw::given(int k, int i, int j) const
{
  return pair->given(cols[k], i, j);
}

const double *PDFailureLaw::table(int k) const
{
  return pair->coef[cols[k]][0];
}

const PDFailureLaw &PDFailureLaw::law_of(int i, int j) const
{
  return pair->law_of(pair->coef[pair->ifail][i][j]);
}

void PDFailureLaw::take(PDCoefLine &line, int k, const char *text) const
{
  const pd_coef &c = coefs[k];
  pair->set_on_line(line, cols[k], pair->finite_number(c.label ? c.label : c.name, text));
}

int PDFailureLaw::take_keyword(PDCoefLine &line, int k, int narg, char **arg, int iarg) const
{
  if (iarg + 1 < narg && strcmp(arg[iarg], coefs[k].name) == 0) {
    take(line, k, arg[iarg + 1]);
    return iarg + 2;
  }
  return iarg;
}

bool PDFailureLaw::line_keyword(const char *word) const
{
  return strcmp(word, "fail") == 0 || strcmp(word, "nobond") == 0 || pair->coef_index(word) >= 0;
}

int PDFailureLaw::fail_column() const
{
  return pair->ifail;
}

const char *PDFailureLaw::column_name(int p) const
{
  return pair->decl[p].name;
}

std::string PDFailureLaw::usages_of(int p) const
{
  return pair->law_usages(p);
}

double &PDFailureLaw::column(const char *name, int i, int j)
{
  return pair->coef[pair->coef_index(name)][i][j];
}

const char *PDFailureLaw::style() const
{
  return pair->style_name();
}

int PDFailureLaw::dim() const
{
  return pair->dim();
}

bool PDFailureLaw::plane_strain() const
{
  return pair->model_dim == PD_PLANE_STRAIN;
}

bool PDFailureLaw::legacy_mode() const
{
  return pair->legacy;
}

FixPDBonds *PDFailureLaw::bonds() const
{
  return pair->bonds;
}

double *PDFailureLaw::field(const char *name) const
{
  const int id = pair->field_index(name);
  return id < 0 ? nullptr : pair->bonds->field(id);
}

void PDFailureLaw::check_derived(int k, int i, int j)
{
  pair->check_derived(cols[k], i, j);
}
