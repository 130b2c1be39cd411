/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: common part of the pd/ material pair styles.
------------------------------------------------------------------------- */

#include "pair_pd.h"

#include "atom.h"
#include "comm.h"
#include "compute_pd_atom.h"
#include "domain.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "force.h"
#include "lattice.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pd_cell_shares.h"
#include "pd_compat.h"
#include "pd_error.h"
#include "pd_failure_law.h"
#include "update.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>

extern "C" {
#include "pd_contact.h"
#include "pd_influence.h"
#include "pd_material_file.h"
#include "pd_quadrature.h"
#include "pd_timestep.h"
}

using namespace LAMMPS_NS;

static const char *const FIX_ID = "PD_BONDS";

// The law each type pair names: a row of core/pd_laws.h (the larger between
// two types: the law of the one that fails, since all pairs share one).
static const pd_coef FAIL_COEF = {"fail", "failure law", PD_MIX_MAX, PD_COEF_PAIR, PD_CHECK_FINITE,
                                  0.0, 0.0, 0.0, nullptr};

PairPD::PairPD(LAMMPS *lmp, const pd_coef *material_coefs, int ncoefs) :
    Pair(lmp), decl(material_coefs, material_coefs + ncoefs), nmaterial(ncoefs), ifail(ncoefs),
    coef(nullptr), legacy(0), recontact(RECONTACT_NEAR), quadrature(QUADRATURE_POINT), cell_beyond(0.0), law(nullptr), model_dim(PD_3D),
    thickness(0.0), lattice_spacing(0.0), bonds(nullptr), report_pending(0), timed_since(-1.0), work(nullptr), nwork(0),
    released(nullptr), fresh(nullptr), maxfresh(0), nreleased(0), dt_estimate(0.0),
    reaction(nullptr), nreaction(0), radius(nullptr),
    nradius(0), radius_step(-1)
{
  // the columns: the material's, the law of each pair, then every law's
  // coefficients (a name two laws declare is one column: its first
  // declaration mixes it)
  decl.push_back(FAIL_COEF);
  laws = pd_failure_laws(this);
  for (auto &l : laws)
    for (const pd_coef &c : l->coefs) {
      int p = coef_index(c.name);
      if (p < 0) {
        p = decl.size();
        decl.push_back(c);
        decl.back().label = nullptr;
      }
      l->cols.push_back(p);
    }
  law = laws[0].get();
  restartinfo = 1;
  single_enable = 0;
  no_virial_fdotr_compute = 1;
  manybody_flag = 1;
  // a test hook: the kernels' two ways must agree to the bit
  // (unittest/lammps/test_kernels.py compares them)
  const char *by_bond = getenv("PDEXT_BOND_BY_BOND");
  bond_by_bond = by_bond && *by_bond && strcmp(by_bond, "0") != 0;
}

PairPD::~PairPD()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    for (size_t p = 0; p < decl.size(); p++) memory->destroy(coef[p]);
    delete[] coef;
  }
  memory->destroy(work);
  memory->destroy(released);
  memory->destroy(reaction);
  free(fresh);
  memory->destroy(radius);
}

void PairPD::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  coef = new double **[decl.size()];
  for (size_t p = 0; p < decl.size(); p++) {
    memory->create(coef[p], n + 1, n + 1, "pair:coef");
    for (int i = 0; i <= n; i++)
      for (int j = 0; j <= n; j++) coef[p][i][j] = NAN;
  }
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) setflag[i][j] = 0;
}

// The material is the pair style, or the hybrid sub-style, that is a
// PairPD (pd/contact is not one: it stores no bonds).
PairPD *PairPD::active(Force *force)
{
  for (Pair *p : PDCompat::pair_styles(force))
    if (auto *material = dynamic_cast<PairPD *>(p)) return material;
  return nullptr;
}

double PairPD::smallest_horizon() const
{
  double h = INFINITY;
  for (int t = 1; t <= atom->ntypes; t++)
    if (setflag[t][t]) h = MIN(h, horizon(t, t));
  return h;
}

bool PairPD::given(int p, int i, int j) const
{
  return !std::isnan(coef[p][i][j]);
}

int PairPD::coef_index(const std::string &name) const
{
  for (size_t p = 0; p < decl.size(); p++)
    if (name == decl[p].name) return (int) p;
  return -1;
}

// A coefficient as messages name it: "critical stretch s0"
std::string PairPD::describe(const pd_coef &c) const
{
  const char *name = c.label ? c.label : c.name;
  return c.what ? fmt::format("{} {}", c.what, name) : name;
}

PDFailureLaw *PairPD::law_named(const char *name) const
{
  for (auto &l : laws)
    if (l->selectable() && strcmp(name, l->name) == 0) return l.get();
  return nullptr;
}

PDFailureLaw &PairPD::law_of(double id) const
{
  const int k = std::isnan(id) ? 0 : (int) id;
  return *laws[k >= 0 && k < (int) laws.size() ? k : 0];
}

// The names of the laws that 'fail' takes: "stretch, energy or legacy"
std::string PairPD::law_names(const char *last) const
{
  std::vector<std::string> n;
  for (auto &l : laws)
    if (l->selectable()) n.push_back(l->name);
  std::string s;
  for (size_t k = 0; k < n.size(); k++)
    s += (k == 0 ? "" : (k + 1 == n.size() ? last : ", ")) + n[k];
  return s;
}

// The syntax of the laws that take a failure coefficient under its own
// name: "'fail stretch <s0> | fail stretch Gc <Gc>'"
std::string PairPD::law_usages(int col) const
{
  std::string s;
  for (auto &l : laws) {
    const pd_coef *c = l->entry(col);
    if (c && !c->label) s += fmt::format("{}'{}'", s.empty() ? "" : " or ", l->usage());
  }
  return s;
}

/* ---------------------------------------------------------------------- */

void PairPD::settings(int narg, char **arg)
{
  legacy = 0;
  recontact = RECONTACT_NEAR;
  quadrature = -1;    // not given: the style's default, below
  directional = -1;    // not given: yes where the style offers it, except legacy
  model_dim = PD_3D;
  thickness = 0.0;
  const std::string style = style_name();
  int iarg = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "legacy") == 0 || strcmp(arg[iarg], "norecontact") == 0) {
      if (arg[iarg][0] == 'l') legacy = 1;
      else recontact = RECONTACT_NONE;
      iarg++;
      continue;
    }
    if (strcmp(arg[iarg], "recontact") == 0) {
      const char *mode = iarg + 1 < narg ? arg[iarg + 1] : "";
      if (strcmp(mode, "near") == 0) recontact = RECONTACT_NEAR;
      else if (strcmp(mode, "any") == 0) recontact = RECONTACT_ANY;
      else if (strcmp(mode, "none") == 0) recontact = RECONTACT_NONE;
      else error->all(FLERR, "Pair style {}: 'recontact {}': expected near, any or none", style, mode);
      iarg += 2;
      continue;
    }
    if (strcmp(arg[iarg], "quadrature") == 0) {
      const char *rule = iarg + 1 < narg ? arg[iarg + 1] : "";
      if (strcmp(rule, "point") == 0) quadrature = QUADRATURE_POINT;
      else if (strcmp(rule, "partial") == 0) quadrature = QUADRATURE_PARTIAL;
      else error->all(FLERR, "Pair style {}: 'quadrature {}': expected point or partial", style, rule);
      iarg += 2;
      continue;
    }
    if (strcmp(arg[iarg], "directional_correction") == 0) {
      const char *yes = iarg + 1 < narg ? arg[iarg + 1] : "";
      if (strcmp(yes, "yes") == 0) directional = 1;
      else if (strcmp(yes, "no") == 0) directional = 0;
      else error->all(FLERR, "Pair style {}: 'directional_correction {}': expected yes or no", style, yes);
      iarg += 2;
      continue;
    }
    if (strcmp(arg[iarg], "plane") == 0 || strcmp(arg[iarg], "thickness") == 0) {
      if (domain->dimension != 2)
        error->all(FLERR, "Pair style {}: '{}' is a 2D option (dimension 2)", style, arg[iarg]);
      if (iarg + 1 >= narg) error->all(FLERR, "Pair style {}: '{}' needs a value", style, arg[iarg]);
      if (strcmp(arg[iarg], "thickness") == 0) {
        thickness = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
        if (!(thickness > 0.0) || !std::isfinite(thickness))
          error->all(FLERR, "Pair style {}: thickness must be a positive finite number, got '{}'",
                     style, arg[iarg + 1]);
      } else if (strcmp(arg[iarg + 1], "stress") == 0) model_dim = PD_PLANE_STRESS;
      else if (strcmp(arg[iarg + 1], "strain") == 0) model_dim = PD_PLANE_STRAIN;
      else error->all(FLERR, "Pair style {}: 'plane {}': expected stress or strain", style, arg[iarg + 1]);
      iarg += 2;
      continue;
    }
    const int used = parse_setting(narg, arg, iarg);
    if (!used) error->all(FLERR, "Pair style {}: unknown keyword '{}'", style_name(), arg[iarg]);
    iarg += used;
  }
  if (quadrature < 0) quadrature = legacy ? QUADRATURE_POINT : default_quadrature();
  if (legacy && partial_volumes())
    error->all(FLERR, "Pair style {}: 'quadrature partial' and 'legacy' do not go together: legacy "
               "reproduces PERI, which has its own partial volumes; drop one of them", style);
  int power;
  if (directional < 0) directional = directional_moment(power) && !legacy;
  if (directional && !directional_moment(power))
    error->all(FLERR, "Pair style {}: 'directional_correction' is for pd/bond and pd/ordinary ({} is exact on "
               "any family with 'strain extended')", style, style);
  if (directional && legacy)
    error->all(FLERR, "Pair style {}: 'directional_correction' and 'legacy' do not go together: legacy "
               "reproduces PERI's families as they are; drop one of them", style);
  if (domain->dimension == 2 && (model_dim == PD_3D || thickness == 0.0))
    error->all(FLERR, "Pair style {} in 2D needs 'plane stress' or 'plane strain' and "
               "'thickness <t>' (the plate thickness; volumes are area x thickness)", style);
}

int PairPD::parse_setting(int, char **, int)
{
  return 0;
}

void PairPD::coeff(int narg, char **arg)
{
  if (narg < 2) error->all(FLERR, "Incorrect args for pair coefficients");
  if (!allocated) allocate();
  if (narg > 2 && strcmp(arg[2], "file") == 0) return read_material_file(narg, arg);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  int iarg = 2;
  if (iarg < narg && parse_model(arg[iarg])) iarg++;
  const std::vector<double> values = parse_values(narg, arg, iarg, std::vector<double>(decl.size(), NAN));
  // a line that sets no type's own pair (I I) must not carry a type's
  // material: it would be silently unused
  if (ihi < jlo || jhi < ilo)
    for (size_t p = 0; p < decl.size(); p++)
      if (!std::isnan(values[p]) && !(decl[p].flags & PD_COEF_PAIR))
        error->all(FLERR, "Pair {} coeff {} {}: '{}' belongs on a type's own line (I I); a line between "
                   "two types sets only the horizon and failure of their bonds", style_name(), arg[0], arg[1],
                   decl[p].name);
  if (set_coeff_pairs(ilo, ihi, jlo, jhi, values) == 0)
    error->all(FLERR, "Incorrect args for pair coefficients");
}

// A number that must be finite: overflow (1e400), inf and nan are refused
// by the key's name, since they would reach the physics as NaN or zero.
double PairPD::finite_number(const char *key, const char *text)
{
  const double v = utils::numeric(FLERR, text, false, lmp);
  if (!std::isfinite(v))
    error->all(FLERR, "Pair {} coeff: '{}' must be a finite number, got '{}'", style_name(), key, text);
  return v;
}

// A value read from the line; a key given twice on one line is an error.
void PairPD::set_on_line(PDCoefLine &line, int p, double v)
{
  if (line.seen[p])
    error->all(FLERR, "Pair {} coeff: '{}' is given twice on one line", style_name(), decl[p].name);
  line.seen[p] = 1;
  line.values[p] = v;
}

// keyword/value pairs from arg[iarg] on, over the given values (a material
// file's, or NaN)
std::vector<double> PairPD::parse_values(int narg, char **arg, int iarg, std::vector<double> values)
{
  const std::string style = style_name();
  PDCoefLine line = {values, std::vector<char>(decl.size(), 0)};
  while (iarg < narg) {
    if (strcmp(arg[iarg], "nobond") == 0) {
      // two types that must not bond (an impactor and its target)
      set_on_line(line, 0, 0.0);
      iarg++;
      continue;
    }
    if (strcmp(arg[iarg], "fail") == 0) {
      // fail <law> and the law's own words (pd_law_<law>.cpp)
      if (iarg + 1 >= narg)
        error->all(FLERR, "Pair {} coeff: 'fail' needs a law: {}", style, law_names(" or "));
      PDFailureLaw *l = law_named(arg[iarg + 1]);
      if (!l)
        error->all(FLERR, "Pair {} coeff: unknown failure law '{}' ({})", style, arg[iarg + 1], law_names(", "));
      set_on_line(line, ifail, l->id);
      iarg = l->parse(line, narg, arg, iarg + 2);
      continue;
    }
    const int p = coef_index(arg[iarg]);
    if (p < 0) {
      std::string known;
      for (auto &c : decl) known += std::string(" ") + c.name;
      const bool number = utils::is_double(arg[iarg]);
      error->all(FLERR, "Pair {} coeff: {} '{}' (expected keyword/value pairs, keywords:{} nobond){}",
                 style, number ? "a value where a keyword belongs:" : "unknown keyword", arg[iarg],
                 known, number ? "; with 'file', give one material name per atom type" : "");
    }
    if (iarg + 1 >= narg)
      error->all(FLERR, "Pair {} coeff: keyword '{}' needs a value", style, arg[iarg]);
    set_on_line(line, p, finite_number(arg[iarg], arg[iarg + 1]));
    iarg += 2;
  }
  law_of(line.values[ifail]).settle(line);
  return line.values;
}

int PairPD::set_coeff_pairs(int ilo, int ihi, int jlo, int jhi, const std::vector<double> &values)
{
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      for (size_t p = 0; p < decl.size(); p++) coef[p][i][j] = values[p];
      if (values[0] == 0.0) {
        set_nobond(i, j);
      } else {
        check_declared(i, j);
        check_coeff(i, j);
        check_failure(i, j);
      }
      setflag[i][j] = 1;
      count++;
    }
  return count;
}

// The material's values of one type pair against their declarations:
// given where required, valid, defaults where it may be given.
void PairPD::check_declared(int i, int j)
{
  for (int p = 0; p < nmaterial; p++) {
    const pd_coef &c = decl[p];
    if ((c.flags & PD_COEF_REQUIRED) && !(given(p, i, j) && pd_coef_valid(&c, value(p, i, j))))
      error->all(FLERR, "Pair {} coeff {} {}: {} missing{}", style_name(), i, j, describe(c),
                 c.check == PD_CHECK_POSITIVE ? " or not positive"
                 : c.check == PD_CHECK_RANGE  ? fmt::format(" or outside [{}, {}]", c.lo, c.hi)
                                              : "");
    check_value(c, p, i, j);
    if (!given(p, i, j) && (c.flags & PD_COEF_DEFAULT) && (i == j || (c.flags & PD_COEF_PAIR)))
      coef[p][i][j] = c.value;
  }
}

// A given value of column p against a declaration of it
void PairPD::check_value(const pd_coef &c, int p, int i, int j)
{
  const double v = value(p, i, j);
  if (!given(p, i, j) || pd_coef_valid(&c, v)) return;
  if (c.check == PD_CHECK_POSITIVE && v > 0.0)
    error->all(FLERR, "Pair {} coeff {} {}: {} = {} is below the smallest normal number ({}): "
               "check its magnitude and units", style_name(), i, j, describe(c), v, DBL_MIN);
  if (c.check == PD_CHECK_POSITIVE)
    error->all(FLERR, "Pair {} coeff {} {}: {} must be positive, got {}", style_name(), i, j, describe(c), v);
  error->all(FLERR, "Pair {} coeff {} {}: {} = {} is outside [{}, {}]", style_name(), i, j, describe(c), v,
             c.lo, c.hi);
}

// Horizon 0 ('nobond'): two types that never bond; such a line carries nothing else.
void PairPD::set_nobond(int i, int j)
{
  if (i == j)
    error->all(FLERR, "Pair {} coeff {} {}: 'nobond' (horizon 0) is for a line between two types; a "
               "type's own horizon must be positive", style_name(), i, j);
  for (size_t p = 1; p < decl.size(); p++)
    if (given(p, i, j))
      error->all(FLERR, "Pair {} coeff {} {}: a 'nobond' line (horizon 0) takes no '{}': those "
                 "types share no bonds", style_name(), i, j, decl[p].name);
  check_failure(i, j);    // none
}

// pair_coeff * * file <path> <material per type> [model] [key value ...]:
// each type's constants from the file (keys this style knows), the line's
// values on top; unlike types mix (init_one) unless given by another line.
void PairPD::read_material_file(int narg, char **arg)
{
  const std::string style = style_name();
  const int ntypes = atom->ntypes;
  // the files hold SI values, used as they are
  if (strcmp(update->unit_style, "si") != 0)
    error->all(FLERR, "Pair {} coeff file: material files hold SI values (Pa, J/m^2) and need 'units si'; "
               "with units {} give the constants on the pair_coeff line", style, update->unit_style);
  if (strcmp(arg[0], "*") != 0 || strcmp(arg[1], "*") != 0)
    error->all(FLERR, "Pair {} coeff file: use 'pair_coeff * * file <path> <one material per type>'", style);
  if (narg < 4 + ntypes)
    error->all(FLERR, "Pair {} coeff file: expected a path and {} material names", style, ntypes);
  for (int t = 1; t <= ntypes; t++)
    if (coef_index(arg[3 + t]) >= 0 || strcmp(arg[3 + t], "fail") == 0 || strcmp(arg[3 + t], "nobond") == 0)
      error->all(FLERR, "Pair {} coeff file: expected {} material names (one per atom type, NULL "
                 "for a type without), but type {}'s is the keyword '{}'", style, ntypes, t, arg[3 + t]);
  // rank 0 reads; every rank learns the outcome, so that the error is
  // collective and reaches the log
  std::string text;
  int len = -1;
  if (comm->me == 0) {
    FILE *fp = utils::open_potential(arg[3], lmp, nullptr);
    if (fp) {
      char buf[4096];
      size_t n;
      while ((n = fread(buf, 1, sizeof buf, fp)) > 0) text.append(buf, n);
      fclose(fp);
      len = text.size();
    }
  }
  MPI_Bcast(&len, 1, MPI_INT, 0, world);
  if (len < 0) pd_error_all(lmp, FLERR, fmt::format("Pair {} coeff file: cannot open '{}'", style, arg[3]));
  text.resize(len);
  MPI_Bcast(&text[0], len, MPI_CHAR, 0, world);
  // the parser reads C text: a NUL would end the file there, unseen
  const size_t nul = text.find('\0');
  if (nul != std::string::npos)
    error->all(FLERR, "Pair {} coeff file '{}': a NUL byte on line {} (byte {}): not a text file, or a "
               "damaged one", style, arg[3], 1 + std::count(text.begin(), text.begin() + nul, '\n'), nul + 1);

  int iarg = 4 + ntypes;
  if (iarg < narg && parse_model(arg[iarg])) iarg++;
  // one name more than types (a material of the file or NULL where a
  // keyword belongs): say so, not "unknown keyword"
  if (iarg < narg && coef_index(arg[iarg]) < 0 && strcmp(arg[iarg], "fail") != 0 &&
      strcmp(arg[iarg], "nobond") != 0) {
    pd_material extra;
    char unused[512];
    if (strcmp(arg[iarg], "NULL") == 0 || pd_material_find(text.c_str(), arg[iarg], &extra, unused, sizeof unused) == 0)
      error->all(FLERR, "Pair {} coeff file: more material names than the {} atom type{}: '{}' follows "
                 "type {}'s (one name per type, NULL for a type without)", style, ntypes,
                 ntypes > 1 ? "s" : "", arg[iarg], ntypes);
  }
  for (int t = 1; t <= ntypes; t++) {
    const char *name = arg[3 + t];
    if (strcmp(name, "NULL") == 0) continue;
    pd_material mat;
    char err[512];
    if (pd_material_find(text.c_str(), name, &mat, err, sizeof err))
      error->all(FLERR, "Pair {} coeff file '{}': {}", style, arg[3], err);
    std::vector<double> values(decl.size(), NAN);
    std::string skipped;
    for (size_t p = 0; p < decl.size(); p++) {
      if (!(decl[p].flags & PD_COEF_FILE)) continue;
      const double v = pd_material_get(&mat, decl[p].name);
      if (!std::isnan(v) && !uses_coefficient(p)) skipped += std::string(" ") + decl[p].name;
      else values[p] = v;
    }
    if (!skipped.empty() && comm->me == 0)
      utils::logmesg(lmp, "{} coeff file: material {} (type {}): not used by these settings:{}\n", style,
                     name, t, skipped);
    set_coeff_pairs(t, t, t, t, parse_values(narg, arg, iarg, values));
  }
}

// The 3D material constants of a type pair from K and G, or from E and nu.
pd_elastic PairPD::elastic(int i, int j, const char *who)
{
  const int pK = coef_index("K"), pG = coef_index("G"), pE = coef_index("E"), pnu = coef_index("nu");
  const bool kg = given(pK, i, j) || given(pG, i, j), enu = given(pE, i, j) || given(pnu, i, j);
  pd_elastic m;
  if (kg == enu)
    error->all(FLERR, "Pair {} coeff {} {}: give the elastic constants as K and G or as E and nu", who, i, j);
  const int a = kg ? pK : pE, b = kg ? pG : pnu;
  for (int p : {a, b})
    if (!given(p, i, j)) error->all(FLERR, "Pair {} coeff {} {}: {} missing", who, i, j, decl[p].name);
  const int bad = kg ? pd_elastic_from_K_G(value(a, i, j), value(b, i, j), &m)
                     : pd_elastic_from_E_nu(value(a, i, j), value(b, i, j), &m);
  if (bad)
    error->all(FLERR, "Pair {} coeff {} {}: {} = {} and {} = {} are not an isotropic elastic "
               "material (need K, G, E > 0 and -1 < nu < 1/2)", who, i, j, decl[a].name,
               value(a, i, j), decl[b].name, value(b, i, j));
  return m;
}

pd_elastic PairPD::complete_elastic(int i, int j)
{
  const pd_elastic m = elastic(i, j, style_name());
  const int pK = coef_index("K"), pG = coef_index("G"), pE = coef_index("E"), pnu = coef_index("nu");
  coef[pK][i][j] = m.K;
  coef[pG][i][j] = m.G;
  coef[pE][i][j] = m.E;
  coef[pnu][i][j] = m.nu;
  for (int p : {pK, pG, pE}) check_derived(p, i, j);
  return m;
}

void PairPD::mean_elastic(int i, int j, double &E, double &nu) const
{
  const int pE = coef_index("E"), pnu = coef_index("nu");
  E = 0.5 * (value(pE, i, i) + value(pE, j, j));
  nu = 0.5 * (value(pnu, i, i) + value(pnu, j, j));
}

double PairPD::init_one(int i, int j)
{
  if (setflag[i][j] == 0) {
    // bonds between two types without a line of their own: each column by
    // its declared rule (MS07 eq. 30-31: the mean of the two materials, the
    // larger horizon, the smaller critical stretch)
    for (size_t p = 0; p < decl.size(); p++) {
      if (decl[p].mix == PD_MIX_NONE && i != j && (given(p, i, i) || given(p, j, j)))
        error->all(FLERR, "Pair {} coeff {} {}: '{}' does not mix between types: give it on a "
                   "'pair_coeff {} {}' line", style_name(), i, j, decl[p].name, i, j);
      coef[p][i][j] = pd_coef_mixed(decl[p].mix, coef[p][i][i], coef[p][j][j]);
    }
  }
  // what the pair's failure law derives for bonds between the types
  if (i != j) law_of(coef[ifail][i][j]).mix(i, j, setflag[i][j]);
  for (size_t p = 0; p < decl.size(); p++) coef[p][j][i] = coef[p][i][j];
  // partial cells reach past the horizon: the neighbour lists and ghosts must see them
  return horizon(i, j) > 0.0 ? horizon(i, j) + cell_beyond : horizon(i, j);
}

// Two pd/ material sub-styles of a hybrid would share one bond store.
void PairPD::check_one_material_style()
{
  int instances = 0;
  for (Pair *p : PDCompat::pair_styles(force)) instances += dynamic_cast<PairPD *>(p) != nullptr;
  if (instances > 1)
    error->all(FLERR, "Pair {}: one pd/ material style per simulation (they would share the "
               "bond families); use one style with several atom types", style_name());
}

void PairPD::init_style()
{
  check_one_material_style();
  mix_interfaces();
  select_law();
  check_minimize();
  check_atom_setup();
  check_spacing();
  check_box();
  take_lattice_spacing();
  attach_bond_store();
  report_pending = 1;    // report and per-run set-up at the first compute
}

// Interface pairs not given explicitly are mixed now (LAMMPS mixes them
// after init_style), so that the horizons and the bond fingerprint are
// complete when the bond store takes them; init_one is idempotent.
void PairPD::mix_interfaces()
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) init_one(i, j);
}

// minimize's line search evaluates trial states it may reject: bonds must
// not break or yield there.
void PairPD::check_minimize()
{
  if (update->whichflag == 2 && (law->breaks() || yields()))
    error->all(FLERR, "Pair {}: minimize with bond failure or plasticity is not supported (line "
               "search trial states would break or yield bonds); for quasi-static loading use fix "
               "pd/adr", style_name());
}

// What the bonds need of the atoms and of LAMMPS.
void PairPD::check_atom_setup()
{
  const std::string style = style_name();
  if (!atom->vfrac_flag || !atom->rmass_flag || !atom->x0)
    error->all(FLERR, "Pair {} requires an atom style with per-atom volume, density and reference "
                      "positions (atom_style peri)", style);
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "Pair {} requires an atom map: add 'atom_modify map array' before the box "
                      "is created", style);
  if (!force->newton_pair)
    error->all(FLERR, "Pair {} stores each bond once and needs 'newton on' (the default)", style);
}

// Every atom needs a volume; the horizon must reach past the spacing.
void PairPD::check_spacing()
{
  const std::string style = style_name();
  double hmin = INFINITY;
  for (int i = 1; i <= atom->ntypes; i++) hmin = MIN(hmin, horizon(i, i));
  int bad = 0;
  double spacing = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->vfrac[i] > 0.0)) bad = 1;
    else spacing = MAX(spacing, dim() == 3 ? cbrt(atom->vfrac[i]) : sqrt(atom->vfrac[i] / thickness));
  }
  int anybad;
  MPI_Allreduce(&bad, &anybad, 1, MPI_INT, MPI_MAX, world);
  if (anybad)
    error->all(FLERR, "Pair {}: some atoms have zero volume; set it with 'set ... volume'", style);
  double maxspacing;
  MPI_Allreduce(&spacing, &maxspacing, 1, MPI_DOUBLE, MPI_MAX, world);
  // a bond's cell is the mean of its two atoms' volumes: never larger
  cell_beyond = partial_volumes() ? pd_cell_reach(dim(), maxspacing) : 0.0;
  if (hmin < 1.01 * maxspacing)
    error->all(FLERR, "Pair {}: horizon {} is not larger than the particle spacing {} ({}): "
               "families would have almost no bonds; use about 3 spacings", style, hmin, maxspacing,
               dim() == 3 ? "cube root of the volume" : "square root of volume / thickness");
}

// A horizon longer than the whole box bonds every particle to every other
// (a unit slip), and LAMMPS would stop in its neighbor binning; a periodic
// box must hold two horizons.
void PairPD::check_box()
{
  const std::string style = style_name();
  double cutmax = 0.0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) cutmax = MAX(cutmax, horizon(i, j));
  double side = 0.0;
  const double reach = cutmax + cell_beyond;
  for (int d = 0; d < domain->dimension; d++) side = MAX(side, domain->prd[d]);
  if (cutmax > side)
    error->all(FLERR, "Pair {}: horizon {} is longer than the whole box (largest side {}): every "
               "particle would bond to every other; a horizon is usually about 3 particle "
               "spacings (check its units)", style, cutmax, side);
  for (int d = 0; d < domain->dimension; d++)
    if (domain->periodicity[d] && domain->prd[d] <= 2.0 * reach)
      error->all(FLERR, "Pair {}: periodic box length {} is not larger than twice the {} {}", style,
                 domain->prd[d], cell_beyond > 0.0 ? "bonds' reach (horizon + half a cell diagonal)" : "horizon",
                 reach);
}

// Legacy partial volumes need the lattice spacing, taken once (before the
// families exist) and kept in restart files.
void PairPD::take_lattice_spacing()
{
  const std::string style = style_name();
  auto *store = dynamic_cast<FixPDBonds *>(PDCompat::fix_by_id(modify, FIX_ID));
  if (legacy && lattice_spacing == 0.0 && !(store && store->is_built())) {
    const Lattice *lattice = PDCompat::lattice(domain);
    if (!lattice)
      error->all(FLERR, "Pair {} legacy reproduces PERI's partial volumes, which need the lattice "
                 "spacing: define a lattice first (it is saved in restart files)", style);
    if (lattice->xlattice != lattice->ylattice || lattice->xlattice != lattice->zlattice)
      error->all(FLERR, "Pair {} legacy needs a lattice with equal spacing in x, y and z", style);
    lattice_spacing = lattice->xlattice;
  }
}

// The bond store, created at the first run. It takes this style's family
// spec at its own init (family_spec), which comes after the pair styles'.
void PairPD::attach_bond_store()
{
  // families this style built are gone (unfix PD_BONDS): a new store would
  // build them again, healing every broken bond and forgetting the
  // dissipated energy
  if (!PDCompat::fix_by_id(modify, FIX_ID) && had_families)
    error->all(FLERR, "Pair {}: the bond store {} was removed after it held the bond families (unfix "
               "{}?): a new one would heal every broken bond; keep it, or re-issue pair_style to start "
               "the material anew", style_name(), FIX_ID, FIX_ID);
  if (!PDCompat::fix_by_id(modify, FIX_ID))
    modify->add_fix(fmt::format("{} all pd/bonds {} history {}", FIX_ID,
                                uses_weights() ? "weights" : "noweights", history_per_bond()));
  bonds = dynamic_cast<FixPDBonds *>(PDCompat::fix_by_id(modify, FIX_ID));
  if (!bonds) error->all(FLERR, "Fix ID {} is taken by a fix that is not pd/bonds", FIX_ID);
  if (bonds->carries_weights() != uses_weights() || bonds->history_count() != history_per_bond())
    error->all(FLERR, "Pair {}: the bond store {} has bonds with {} and {} history values, this style "
               "needs {} and {}: it was defined by hand or for another pair style; let the pair style "
               "create it", style_name(), FIX_ID, bonds->carries_weights() ? "weights" : "no weights",
               bonds->history_count(), uses_weights() ? "weights" : "no weights", history_per_bond());
  declare_fields();
}

// The families as the bond store builds them: every horizon, the bond
// weight, and the fingerprint of the settings that decide them.
PDFamilySpec PairPD::family_spec() const
{
  PDFamilySpec spec;
  spec.style = style_name();
  spec.key = family_key();
  spec.ntypes = atom->ntypes;
  spec.horizons.resize((size_t) (atom->ntypes + 1) * (atom->ntypes + 1), NAN);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++) spec.horizons[(size_t) i * (atom->ntypes + 1) + j] = horizon(i, j);
  spec.smallest = smallest_horizon();
  spec.unnamed_mixed.assign(spec.horizons.size(), 0);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++) {
      const bool named = setflag[MIN(i, j)][MAX(i, j)], both_ours = setflag[i][i] && setflag[j][j];
      const bool one_fails = law_of(coef[ifail][i][i]).breaks() != law_of(coef[ifail][j][j]).breaks();
      spec.unnamed_mixed[(size_t) i * (atom->ntypes + 1) + j] = i != j && !named && both_ours && one_fails;
    }
  if (partial_volumes()) {
    // the cell: side a from the mean of the two volumes (symmetric in the bond)
    const int d = dim();
    const double t = thickness;
    spec.beyond = cell_beyond;
    auto shares = std::make_shared<PDCellShares>(d);    // shared by the spec's copies
    spec.fraction = [d, t, shares](const PDBondGeometry &g) {
      const double v = 0.5 * (g.vi + g.vj), a = d == 3 ? cbrt(v) : sqrt(v / t);
      return (*shares)(g.xi, a, g.horizon);
    };
  }
  spec.weight = weight_rule();    // used only when the bonds carry weights
  return spec;
}

// A fingerprint of everything that decides which bonds exist and what they
// store, exactly representable as a double (52 bits of FNV-1a).
double PairPD::family_key() const
{
  std::string s = fmt::format("{}|{}|{}|{}|{}|{}|{}", style_name(), legacy, lattice_spacing,
                              (int) model_dim, uses_weights(), history_per_bond(), family_settings());
  if (partial_volumes()) s += "|quadrature partial";    // (point: the key of files written before the option)
  if (directional) s += "|directional";
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) s += fmt::format("|{}", horizon(i, j));
  uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ULL;
  return (double) (h >> 12);
}

// The failure law of the run: the one every type pair that fails names.
void PairPD::select_law()
{
  law = laws[0].get();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      PDFailureLaw &l = law_of(setflag[i][j] ? coef[ifail][i][j] : NAN);
      if (l.breaks() && law->breaks() && &l != law)
        error->all(FLERR, "Pair {}: one failure law for all type pairs ({})", style_name(),
                   law_names(" or "));
      if (l.breaks()) law = &l;
    }
  // pair_coeff checked it; a restart file's coefficients were not
  const std::string missing = law->unsupported();
  if (!missing.empty())
    error->all(FLERR, "Pair {}: 'fail {}' needs {}", style_name(), law->name, missing);
}

// The failure law of one type pair ('fail', or none) and its values: what
// it needs of the material, no other law's coefficients, its declared
// checks, then its own (pd_law_<name>.cpp).
void PairPD::check_failure(int i, int j)
{
  const std::string style = style_name();
  PDFailureLaw &l = law_of(coef[ifail][i][j]);
  coef[ifail][i][j] = l.id;
  if (l.breaks()) {
    const std::string missing = l.unsupported();
    if (!missing.empty())
      error->all(FLERR, "Pair {} coeff {} {}: 'fail {}' needs {}", style, i, j, l.name, missing);
    for (int p = ifail + 1; p < (int) decl.size(); p++)
      if (given(p, i, j) && !l.declares(p))
        error->all(FLERR, "Pair {} coeff {} {}: '{}' belongs to {}, not to '{}'", style, i, j,
                   decl[p].name, law_usages(p), l.usage());
    for (size_t k = 0; k < l.coefs.size(); k++) check_value(l.coefs[k], l.cols[k], i, j);
  }
  l.check(i, j);
}

// A coefficient derived from the inputs (micromodulus, critical stretch, Lame
// constants) must come out finite and positive: extreme inputs overflow.
void PairPD::check_derived(int p, int i, int j)
{
  const double v = value(p, i, j);
  if (!std::isnan(v) && !(v >= DBL_MIN && std::isfinite(v)))
    error->all(FLERR, "Pair {} coeff {} {}: the inputs give {} = {}, not a positive finite number; "
               "check the magnitudes and units of the constants", style_name(), i, j, decl[p].name, v);
}

bool PairPD::failing() const
{
  return law->breaks() || bonds->fracture().has_broken();
}

// The failure state for one force evaluation of a failure-aware kernel.
pd_failure PairPD::failure_state()
{
  zero_released();
  pd_failure f = recontact_state();
  f.params = law->evaluation();
  f.law = law->kernels();
  f.note_atom = law->notes();
  f.released_atom = released;
  f.fresh = fresh;
  f.maxfresh = maxfresh;
  // a second evaluation of the step in which bonds last broke: they act
  // with half their force again, as the first time (see pd_ordinary.c)
  f.replay = law->replays_fresh() && bonds->fracture().unbreak_fresh(bonds->table(), update->ntimestep);
  return f;
}

pd_failure PairPD::recontact_state()
{
  pd_failure f = {};
  f.law = law->id;
  f.recontact = !law->no_recontact() && recontact != RECONTACT_NONE;
  f.contact_radius = f.recontact && recontact == RECONTACT_NEAR ? contact_radii() : nullptr;
  f.len0 = bonds->len0_data();
  return f;
}

// What one evaluation of the material works on: the bonds, this rank's
// atoms, and the tally and failure state when the step asks for them.
void PairPD::begin_evaluation(Evaluation &e)
{
  if (timed_since == 0.0) timed_since = MPI_Wtime();
  e.view = loop_view();
  e.tally = pd_tally{};
  e.tally.eatom = eflag_atom ? eatom : nullptr;
  e.tally.skip_virial = !vflag_global;
  // (LAMMPS zeroes it over owned and ghost atoms; compute stress/atom adds
  // the ghosts' onto their owners)
  e.tally.vatom = vflag_atom && vatom ? vatom[0] : nullptr;
  e.fails = failing();
  e.fail = e.fails ? failure_state() : pd_failure{};
  // one type: the kernels load none
  const int *type = atom->ntypes == 1 ? nullptr : atom->type;
  e.L = {&e.view, type, atom->ntypes + 1, atom->x[0], atom->vfrac, atom->f[0],
         evflag ? &e.tally : nullptr, e.fails ? &e.fail : nullptr, reactions(),
         atom->nlocal + atom->nghost, bond_by_bond};
}

// The bonds as this style's loops walk them: the store's view, with the
// weights the loops may compute themselves.
pd_bond_view PairPD::loop_view() const
{
  pd_bond_view v = bonds->view();
  v.weight_horizon = inverse_weight_horizon();
  return v;
}

void PairPD::begin_pass(Evaluation &e)
{
  e.view = loop_view();
  e.tally = pd_tally{};
  e.fails = bonds->fracture().has_broken();
  e.fail = e.fails ? recontact_state() : pd_failure{};
  const int *type = atom->ntypes == 1 ? nullptr : atom->type;
  e.L = {&e.view, type, atom->ntypes + 1, atom->x[0], atom->vfrac, nullptr, nullptr,
         e.fails ? &e.fail : nullptr, nullptr, 0};
}

void PairPD::force_pass(Evaluation &e, const std::function<void(const pd_loop *)> &pass)
{
  pass(&e.L);
  if (!e.fails || !law->again(e.fail)) return;
  e.fail.params = law->evaluation();
  e.fail.law = law->kernels();
  e.fail.note_atom = law->notes();
  pd_loop L = e.L;
  unused_forces.assign(3 * (size_t) L.nall, 0.0);
  L.f = unused_forces.data();
  L.tally = nullptr;
  pass(&L);
}

void PairPD::catch_up(bool run_ends)
{
  if (law) law->catch_up(run_ends);
}

bool PairPD::end_evaluation(Evaluation &e)
{
  const bool broke = e.fails && account_failure(e.fail);
  if (evflag) tally(e.tally);
  if (timed_since > 0.0) report_cost(e.view, MPI_Wtime() - timed_since);
  return broke;
}

// What the run's first force evaluation cost per bond, with every effect
// the scene chose, on this machine (cold caches: an upper estimate).
void PairPD::report_cost(const pd_bond_view &v, double seconds)
{
  timed_since = -1.0;
  bigint mine = 0, all;
  for (int i = 0; i < v.nowner; i++) mine += v.count[i];
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  double slowest;
  MPI_Allreduce(&seconds, &slowest, 1, MPI_DOUBLE, MPI_MAX, world);
  if (comm->me == 0 && all > 0)
    utils::logmesg(lmp, "{}: first force evaluation: {:.3g} ns per bond per core ({} bonds, {} ranks, "
                   "{:.3g} s; caches cold, so an upper estimate)\n", style_name(),
                   1e9 * slowest * comm->nprocs / (double) all, all, comm->nprocs, slowest);
}

// Half the particle spacing of every atom (owned + ghost), as pd/contact's
// node radius: where broken bonds start to push. Volumes are fixed, so the
// array changes only when the ghosts do (reneighboring).
const double *PairPD::contact_radii()
{
  const int nall = atom->nlocal + atom->nghost;
  if (nradius < nall || radius_step != neighbor->ncalls) {
    if (atom->nmax > nradius) {
      nradius = atom->nmax;
      memory->destroy(radius);
      memory->create(radius, nradius, "pair:radius");
    }
    for (int i = 0; i < nall; i++) radius[i] = pd_contact_radius(dim(), atom->vfrac[i], thickness);
    radius_step = neighbor->ncalls;
  }
  return radius;
}

// The force loop's scratch (pd_loop.reaction): 4 doubles per atom, owned +
// ghost, zero between evaluations (the loop leaves it so).
double *PairPD::reactions()
{
  if (atom->nmax > nreaction) {
    nreaction = atom->nmax;
    memory->destroy(reaction);
    memory->create(reaction, 4 * nreaction, "pair:reaction");
    std::fill_n(reaction, 4 * (size_t) nreaction, 0.0);
  }
  return reaction;
}

// The per-atom energy one evaluation dissipates (owned + ghost). It is zero
// between evaluations: book_released clears what it booked, so that the
// steps in which nothing breaks do not clear it (only a bond that breaks
// writes it, and all ranks book when one breaks a bond).
double *PairPD::zero_released()
{
  if (atom->nmax > nreleased) {
    nreleased = atom->nmax;
    memory->destroy(released);
    memory->create(released, nreleased, "pair:released");
    std::fill(released, released + nreleased, 0.0);
  }
  return released;
}

// Add the per-atom energy of one evaluation to the owners' totals.
void PairPD::book_released()
{
  bonds->sum_to_owners(released);
  double *dissipated = bonds->dissipated_atom();
  for (int i = 0; i < atom->nlocal; i++) dissipated[i] += released[i];
  std::fill(released, released + atom->nlocal + atom->nghost, 0.0);
}

// Book what one evaluation broke: totals on this rank, and the per-atom
// released energy summed onto owners (only on steps where something broke
// somewhere, which all ranks learn together).
bool PairPD::account_failure(const pd_failure &f)
{
  law->after_evaluation();
  fresh = f.fresh;    // the core may have grown it
  maxfresh = f.maxfresh;
  if (f.replay) {
    bonds->fracture().rebreak_fresh(bonds->table());   // also those that did not break again (moved atoms)
    return true;
  }
  int mine = f.nbroken > 0, any;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  if (law->replays_fresh())
    bonds->fracture().note_fresh(bonds->table(), f.fresh, f.nfresh, update->ntimestep, any);
  if (!any) return false;
  bonds->fracture().set_has_broken();
  bonds->fracture().add_broken(f.nbroken);
  bonds->fracture().add_dissipated(f.released, f.released_joule);
  book_released();
  return true;
}

PDFamilySpec::Weight PairPD::weight_rule() const
{
  const int peri = legacy;
  const double spacing = lattice_spacing;
  return [peri, spacing](const PDBondGeometry &g) {
    return peri ? pd_partial_volume_legacy(g.r, g.horizon, spacing) : g.fraction;
  };
}

double PairPD::influence_at(int kind, int dim, const PDBondGeometry &g)
{
  return pd_influence_of_cell((pd_influence_kind) kind, dim, g.r, g.horizon);
}

/* ---------------------------------------------------------------------- */

// The style's per-atom fields, in the bond store (the same ones again at
// each run: the store returns their ids).
// The style's fields, then the calibration's (recomputed at each run's
// set-up, so not in restart files), then the failure law's.
std::vector<PDField> PairPD::fields_to_declare() const
{
  std::vector<PDField> all = per_atom_fields();
  const int moved = PDField::MIGRATE | PDField::OUTPUT;
  all.push_back({"family_share", 1, moved});
  all.push_back({"calibrated_volume", 1, moved});
  if (law)
    for (const PDField &f : law->per_atom_fields()) all.push_back(f);
  return all;
}

bool PairPD::demanded(const std::string &name)
{
  bool due = update->setupflag;
  for (Compute *c : PDCompat::computes(modify)) {
    auto *output = dynamic_cast<ComputePDAtom *>(c);
    // (matchstep only drops the schedule's past steps)
    if (output && output->lists(name) && output->matchstep(update->ntimestep)) due = true;
  }
  if (due) demanded_on[name] = update->ntimestep;
  return due;
}

bigint PairPD::computed_on(const std::string &name) const
{
  const auto it = demanded_on.find(name);
  return it == demanded_on.end() ? -1 : it->second;
}

void PairPD::declare_fields()
{
  declared = fields_to_declare();
  field_id.clear();
  for (const PDField &f : declared) field_id.push_back(bonds->add_field(f));
  calibrated_field = field_index("calibrated_volume");
}

int PairPD::field_index(const std::string &name) const
{
  for (size_t k = 0; k < declared.size() && k < field_id.size(); k++)
    if (declared[k].name == name) return field_id[k];
  return -1;
}

// (under hybrid, the types of other sub-styles have no value here)
double PairPD::shared_value(int p, double none)
{
  int first = 0;
  for (int i = 1; i <= atom->ntypes; i++) {
    if (!setflag[i][i]) continue;
    if (!first) first = i;
    if (coef[p][i][i] != coef[p][first][first])
      error->all(FLERR, "Pair {}: all types need the same {} ({} has {}, {} has {})", style_name(),
                 describe(decl[p]), i, coef[p][i][i], first, coef[p][first][first]);
  }
  return first ? coef[p][first][first] : none;
}

void PairPD::grow_work()
{
  if (atom->nmax > nwork) {
    nwork = atom->nmax;
    memory->destroy(work);
    memory->create(work, 2 * nwork, "pair:work");
  }
}

void PairPD::tally(const pd_tally &t)
{
  if (eflag_global) eng_vdwl += t.energy;
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += t.virial[k];
}

double *PairPD::scratch()
{
  grow_work();
  return work + nwork;
}

void PairPD::sum_to_owners(double *a)
{
  bonds->sum_to_owners(a);
}

void PairPD::note_stable_dt(double dt)
{
  bonds->note_stable_dt(dt);
}

void PairPD::current_stiffness_sums(double *current, double *closing)
{
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) current[i] = closing[i] = 0.0;
  bonds->copy_to_ghosts(atom->v[0], 3);    // LAMMPS sends ghosts no velocity by default
  tangent_sum(current, closing);
  bonds->sum_to_owners(current);
  bonds->max_to_owners(closing);
}

// The stable step of the current state: each particle's bound on its
// current stiffness (as fix pd/timestep takes it, without contact).
double PairPD::current_stable_dt()
{
  const int nall = atom->nlocal + atom->nghost;
  std::vector<double> current(nall), closing(nall);
  current_stiffness_sums(current.data(), closing.data());
  return smallest_stable_dt(current.data());
}

// The smallest stable step (MS07 eq. 43) over the owned atoms for their
// stiffness sums (collective). LAMMPS integrates a = ftm2v f / m: in metal,
// real, electron units the stiffness acts scaled by ftm2v (1 in si, cgs,
// lj, micro, nano).
double PairPD::smallest_stable_dt(const double *stiffness) const
{
  double mine = INFINITY, all;
  for (int i = 0; i < atom->nlocal; i++)
    mine = MIN(mine, pd_stable_dt(atom->rmass[i], force->ftm2v * stiffness[i]));
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_MIN, world);
  return all;
}

void PairPD::reference_stiffness_sums(double *reference)
{
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) reference[i] = 0.0;
  stable_dt_sum(reference);
  bonds->sum_to_owners(reference);
}

void PairPD::max_to_owners(double *a)
{
  bonds->max_to_owners(a);
}

// Horizon and stable time step (MS07 eq. 43), once per run, in the log.
void PairPD::report_setup()
{
  report_pending = 0;
  had_families = bonds->is_built();
  calibrate_families();
  setup_run();
  law->setup_run();
  grow_work();
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) work[i] = 0.0;
  stable_dt_sum(work);
  bonds->sum_to_owners(work);
  const double dt = smallest_stable_dt(work);
  dt_estimate = dt;
  bonds->note_stable_dt(dt);    // for the blow-up guard's message
  if (comm->me == 0) {
    std::string hs;
    // the types of this style only (under hybrid the others have no horizon here)
    for (int i = 1; i <= atom->ntypes; i++)
      if (setflag[i][i]) hs += fmt::format(" {:.6g}", horizon(i, i));
    const char *dims[] = {"3D", "2D plane stress", "2D plane strain"};
    const char *quad = legacy ? "PERI's partial volumes (legacy PERI mode)"
        : partial_volumes() ? "partial volumes (each cell's share inside the horizon, Seleson 2014)"
                            : "point (whole cells within the horizon)";
    utils::logmesg(lmp, "{}: {}{}, horizon{}, quadrature {}; stable time step estimate (MS07 eq. 43) {:.6g}, "
                   "timestep {:.6g} is {:.3f} of it\n", style_name(), dims[model_dim],
                   dim() == 2 ? fmt::format(" (thickness {})", thickness) : "", hs, quad, dt, update->dt,
                   update->dt / dt);
    const char *rule[] = {"never (recontact none)", "once their particles touch (recontact near)",
                          "whenever compressed, at any length (recontact any)"};
    utils::logmesg(lmp, "{}: broken bonds push {}\n", style_name(),
                   law->no_recontact() ? fmt::format("never ({})", law->no_recontact()) : rule[recontact]);
    report_extra();
    law->report();
  }
  report_accuracy(family_spec());
  MPI_Barrier(world);    // rank 0 wrote the report: time the evaluation alone
  timed_since = 0.0;     // the evaluation that follows
  if (update->dt > dt)
    error->warning(FLERR, "Pair {}: timestep {} exceeds the stable estimate {}", style_name(),
                   update->dt, dt);
}

/* ---------------------------------------------------------------------- */

void PairPD::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j])
        for (size_t p = 0; p < decl.size(); p++) fwrite(&coef[p][i][j], sizeof(double), 1, fp);
    }
}

void PairPD::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j])
        for (size_t p = 0; p < decl.size(); p++) {
          if (me == 0) utils::sfread(FLERR, &coef[p][i][j], sizeof(double), 1, fp, nullptr, error);
          MPI_Bcast(&coef[p][i][j], 1, MPI_DOUBLE, 0, world);
        }
    }
}

void PDSettingsIO::operator()(int &v)
{
  if (writing) fwrite(&v, sizeof(int), 1, fp);
  else if (lmp->comm->me == 0) utils::sfread(FLERR, &v, sizeof(int), 1, fp, nullptr, lmp->error);
  if (!writing) MPI_Bcast(&v, 1, MPI_INT, 0, lmp->world);
}

void PDSettingsIO::operator()(double &v)
{
  if (writing) fwrite(&v, sizeof(double), 1, fp);
  else if (lmp->comm->me == 0) utils::sfread(FLERR, &v, sizeof(double), 1, fp, nullptr, lmp->error);
  if (!writing) MPI_Bcast(&v, 1, MPI_DOUBLE, 0, lmp->world);
}

void PairPD::write_restart_settings(FILE *fp)
{
  PDSettingsIO io(lmp, fp, true);
  restart_settings(io);
}

void PairPD::read_restart_settings(FILE *fp)
{
  PDSettingsIO io(lmp, fp, false);
  restart_settings(io);
}

// Files written before 'quadrature' existed start with recontact (0..2);
// later ones with a negative layout mark, then the settings: -2 up to the
// quadrature, -3 also the directional correction.
static constexpr int SETTINGS_LAYOUT_QUADRATURE = -2;
static constexpr int SETTINGS_LAYOUT_DIRECTIONAL = -3;

void PairPD::restart_settings(PDSettingsIO &io)
{
  int dimcode = (int) model_dim;
  int layout = SETTINGS_LAYOUT_DIRECTIONAL;
  io(layout);
  const bool old_layout = layout >= 0;
  if (old_layout) recontact = layout;
  else io(recontact);
  io(legacy);
  if (old_layout) quadrature = QUADRATURE_POINT;
  else io(quadrature);
  io(lattice_spacing);
  io(dimcode);
  io(thickness);
  if (layout <= SETTINGS_LAYOUT_DIRECTIONAL) io(directional);
  else directional = 0;
  model_dim = (pd_dimension) dimcode;
}

double PairPD::memory_usage()
{
  return 2.0 * nwork * sizeof(double);
}
