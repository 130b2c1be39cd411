/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/corr (T14 ch. 2, 4 and 7).

   Per step: the sums of each atom's family over each bond once (shape
   tensor, deformation gradient; extended: the Seth-Hill strain and the
   family's fourth moment), summed onto owners; the law at each owned atom
   (the per-atom tensor work, out of the bond loop); its tensor sent to the
   ghosts; forces over each bond once.
------------------------------------------------------------------------- */

#include "pair_pd_corr.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"
#include "pd_compat.h"
#include "pd_fracture_record.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

extern "C" {
#include "pd_influence.h"
#include "pd_ordinary.h"
#include "pd_params.h"
#include "pd_tangent.h"
}

using namespace LAMMPS_NS;

// doubles per atom of the increment state (a struct of doubles)
static constexpr int INCREMENT = sizeof(pd_corr_increment) / sizeof(double);
static_assert(sizeof(pd_corr_increment) == INCREMENT * sizeof(double), "pd_corr_increment holds doubles only");

static const char *const MODEL_NAMES[] = {"elastic", "neohookean", "j2", "johnson_cook"};
static const int NMODELS = 4;

PairPDCorr::PairPDCorr(LAMMPS *lmp) :
    PairPD(lmp, pd_corr_coefs, PD_CORR_NCOEFS), extended(1), model(-1), influence(-1),
    stabilization(0.0), order(0.0), spring(nullptr), shape_stale(true)
{
}

PairPDCorr::~PairPDCorr()
{
  memory->destroy(spring);
}

void PairPDCorr::settings(int narg, char **arg)
{
  extended = 1;
  model = -1;
  influence = -1;
  stabilization = 0.0;
  PairPD::settings(narg, arg);
  if (model < 0)
    error->all(FLERR, "Pair pd/corr: 'model' missing: elastic, neohookean, j2 or johnson_cook");
}

int PairPDCorr::parse_setting(int narg, char **arg, int iarg)
{
  const char *key = arg[iarg];
  if (strcmp(key, "strain") && strcmp(key, "model") && strcmp(key, "stabilization") &&
      strcmp(key, "influence"))
    return 0;
  if (iarg + 1 >= narg) error->all(FLERR, "Pair pd/corr: '{}' needs a value", key);
  const char *val = arg[iarg + 1];
  if (strcmp(key, "strain") == 0) {
    if (strcmp(val, "extended") == 0) extended = 1;
    else if (strcmp(val, "classical") == 0) extended = 0;
    else error->all(FLERR, "Pair pd/corr: strain '{}': expected classical or extended", val);
  } else if (strcmp(key, "model") == 0) {
    model = -1;
    for (int k = 0; k < NMODELS; k++)
      if (strcmp(val, MODEL_NAMES[k]) == 0) model = k;
    if (model < 0)
      error->all(FLERR, "Pair pd/corr: model '{}': expected elastic, neohookean, j2 or johnson_cook", val);
  } else if (strcmp(key, "stabilization") == 0) {
    stabilization = finite_number("stabilization", val);
    if (stabilization < 0.0)
      error->all(FLERR, "Pair pd/corr: stabilization {}: expected a coefficient >= 0", val);
  } else {
    influence = pd_influence_from_name(val);
    if (influence < 0)
      error->all(FLERR, "Pair pd/corr: unknown influence function '{}' ({})", val, pd_influence_names());
  }
  return 2;
}

std::string PairPDCorr::family_settings() const
{
  return pd_influence_name((pd_influence_kind) influence);
}

// The constants each model reads beyond the elastic ones.
bool PairPDCorr::uses_coefficient(int p) const
{
  const bool j2 = model == PD_CORR_J2, jc = model == PD_CORR_JOHNSON_COOK;
  if (p == PD_CORR_YIELD) return j2 || jc;
  if (p == PD_CORR_HARDENING) return j2;
  if (p >= PD_CORR_JC_B && p < PD_CORR_NCOEFS) return jc;
  return true;
}

// The elastic constants of a type, and the constants its model needs (and
// no others: a constant the model would not use is an error, not ignored).
void PairPDCorr::check_coeff(int i, int j)
{
  if (i != j) return;
  complete_elastic(i, j);

  const bool j2 = model == PD_CORR_J2, jc = model == PD_CORR_JOHNSON_COOK;
  auto need = [&](int p, bool required) {
    const bool used = required && uses_coefficient(p);
    if (used && !given(p, i, j))
      error->all(FLERR, "Pair pd/corr coeff {} {}: model {} needs {} ({})", i, j, MODEL_NAMES[model],
                 decl[p].name, decl[p].what);
    if (!used && given(p, i, j))
      error->all(FLERR, "Pair pd/corr coeff {} {}: {} ({}) is not used by model {}", i, j,
                 decl[p].name, decl[p].what, MODEL_NAMES[model]);
  };
  need(PD_CORR_YIELD, j2 || jc);
  if (j2 && !given(PD_CORR_HARDENING, i, j)) coef[PD_CORR_HARDENING][i][j] = 0.0;
  need(PD_CORR_HARDENING, j2);
  need(PD_CORR_JC_B, jc);
  need(PD_CORR_JC_N, jc);
  const bool heats = jc && given(PD_CORR_T_MELT, i, j), damages = jc && given(PD_CORR_D1, i, j);
  need(PD_CORR_T_MELT, heats);
  need(PD_CORR_HEAT_CAPACITY, heats);
  need(PD_CORR_D1, damages);
  // the options of heating and damage have defaults, so they count as given
  // here: one changed from its default without the constant that switches
  // its effect on would be silently unused
  auto option_of = [&](int first, int last, bool on, const char *needs) {
    for (int p = first; p <= last; p++)
      if (!on && coef[p][i][j] != decl[p].value)
        error->all(FLERR, "Pair pd/corr coeff {} {}: {} ({}) is used only with {}", i, j, decl[p].name,
                   decl[p].what, needs);
  };
  option_of(PD_CORR_T_ROOM, PD_CORR_T_ROOM, heats, "T_melt (thermal softening)");
  option_of(PD_CORR_T_EXP, PD_CORR_T_EXP, heats, "T_melt (thermal softening)");
  option_of(PD_CORR_TAYLOR_QUINNEY, PD_CORR_TAYLOR_QUINNEY, heats, "T_melt (thermal softening)");
  option_of(PD_CORR_D2, PD_CORR_DC, damages, "d1 (Johnson-Cook damage)");
  // the fracture strain at zero triaxiality and rate, d1 + d2, divides the
  // plastic strain: it must be positive
  if (damages && !(value(PD_CORR_D1, i, j) + value(PD_CORR_D2, i, j) > 0.0))
    error->all(FLERR, "Pair pd/corr coeff {} {}: the fracture strain d1 + d2 = {} must be positive "
               "(Johnson-Cook damage)", i, j, value(PD_CORR_D1, i, j) + value(PD_CORR_D2, i, j));
  if (heats && !(value(PD_CORR_T_MELT, i, j) > value(PD_CORR_T_ROOM, i, j)))
    error->all(FLERR, "Pair pd/corr coeff {} {}: T_melt {} must exceed T_room {}", i, j,
               value(PD_CORR_T_MELT, i, j), value(PD_CORR_T_ROOM, i, j));
}

// E and nu of a type's material; between two types, their means
void PairPDCorr::fracture_elastic(int i, int j, double &E, double &nu) const
{
  mean_elastic(i, j, E, nu);
}

void PairPDCorr::init_style()
{
  if (legacy) error->all(FLERR, "Pair pd/corr has no legacy PERI counterpart: drop 'legacy'");
  if (influence < 0) influence = PD_INFLUENCE_CONSTANT;
  if (model_dim == PD_PLANE_STRESS && model != PD_CORR_ELASTIC)
    error->all(FLERR, "Pair pd/corr: plane stress needs model elastic (the {} law has no closed "
               "form for its out-of-plane strain); use plane strain", MODEL_NAMES[model]);
  order = shared_value(PD_CORR_M, 0.0);
  PairPD::init_style();
}

PDFamilySpec::Weight PairPDCorr::weight_rule() const
{
  const auto kind = (pd_influence_kind) influence;
  const int d = dim();
  const PDFamilySpec::Weight partial = PairPD::weight_rule();    // the cell's share with 'quadrature partial'
  return [kind, d, partial](const PDBondGeometry &g) { return influence_at(kind, d, g) * partial(g); };
}

bool PairPDCorr::any_type_gives(int p) const
{
  if (!allocated) return false;
  for (int t = 1; t <= atom->ntypes; t++)
    if (setflag[t][t] && given(p, t, t)) return true;
  return false;
}

// Only the fields the scene asks for: plastic history with a plastic law,
// temperature with thermal softening, damage with Johnson-Cook damage.
std::vector<PDField> PairPDCorr::per_atom_fields() const
{
  const int kept = PDField::OUTPUT | PDField::MIGRATE | PDField::RESTART;
  std::vector<PDField> f = {
      // extended's F is an output (its strain needs G alone), but for the
      // stabilization, which needs it every step
      {"deformation_gradient", 9,
       PDField::OUTPUT | (stabilization > 0.0 ? PDField::FORWARD : extended ? PDField::ON_DEMAND : 0)},
      {"stress", 6, PDField::OUTPUT | PDField::ON_DEMAND},
      {"corr_tensor", 9, PDField::FORWARD},
      // each step's sums, and the family's shape sums (scratch, summed from
      // ghosts onto owners), and its shape (kept until bonds stop acting)
      {"corr_sums", extended ? PD_CORR_SUMS_EXTENDED : PD_CORR_SUMS_CLASSICAL, 0},
      {"corr_shape_sums", extended ? PD_CORR_SHAPE_SUMS_EXTENDED : PD_CORR_SHAPE_SUMS_CLASSICAL, 0},
      {"corr_shape", PD_CORR_SHAPE, PDField::MIGRATE}};
  if (plastic()) {
    f.push_back({"plastic_strain", 1, kept});
    f.push_back({"plastic_tensor", 6, PDField::MIGRATE | PDField::RESTART});
    f.push_back({"plastic_work", 1, kept});
  }
  // Johnson-Cook's rate and temperature make a repeated evaluation flow
  // again: its increment (pd_corr_increment) is kept to repeat it instead
  if (model == PD_CORR_JOHNSON_COOK) f.push_back({"corr_increment", INCREMENT, PDField::MIGRATE | PDField::RESTART});
  if (thermal()) f.push_back({"temperature", 1, kept});
  if (damage()) f.push_back({"jc_damage", 1, kept | PDField::FORWARD});
  return f;
}

double *PairPDCorr::field(const char *name) const
{
  const int id = field_index(name);
  return id < 0 ? nullptr : bonds->field(id);
}

// Per run: each type's law, and the springs of broken bonds in contact.
void PairPDCorr::setup_run()
{
  const int ntypes = atom->ntypes;
  material.assign(ntypes + 1, pd_corr_material{});
  for (int t = 1; t <= ntypes; t++) {
    if (!setflag[t][t]) continue;
    pd_corr_material &m = material[t];
    m.model = (pd_corr_model) model;
    const double K = value(PD_CORR_K, t, t), G = value(PD_CORR_G, t, t);
    m.mu = G;
    m.lambda = K - 2.0 * G / 3.0;
    m.plane_stress = model_dim == PD_PLANE_STRESS;
    auto v = [&](int p) { return given(p, t, t) ? value(p, t, t) : 0.0; };
    m.yield = v(PD_CORR_YIELD);
    m.hardening = v(PD_CORR_HARDENING);
    m.jc_b = v(PD_CORR_JC_B);
    m.jc_n = v(PD_CORR_JC_N);
    m.jc_c = v(PD_CORR_JC_C);
    m.jc_rate0 = v(PD_CORR_JC_RATE0);
    m.thermal = given(PD_CORR_T_MELT, t, t) && model == PD_CORR_JOHNSON_COOK;
    m.t_room = v(PD_CORR_T_ROOM);
    m.t_melt = v(PD_CORR_T_MELT);
    m.t_exp = v(PD_CORR_T_EXP);
    m.heat_capacity = v(PD_CORR_HEAT_CAPACITY);
    m.taylor_quinney = v(PD_CORR_TAYLOR_QUINNEY);
    m.damage = given(PD_CORR_D1, t, t) && model == PD_CORR_JOHNSON_COOK;
    for (int k = 0; k < 5; k++) m.d[k] = v(PD_CORR_D1 + k);
  }
  memory->destroy(spring);
  memory->create(spring, (ntypes + 1) * (ntypes + 1), "pair:spring");
  for (int i = 0; i <= ntypes; i++)
    for (int j = 0; j <= ntypes; j++)
      spring[i * (ntypes + 1) + j] = i && j && setflag[i][i] && setflag[j][j] ? contact_micromodulus(i, j) : 0.0;
  fill_reference_vectors();
  shape_stale = true;
  // a new atom (or a first run) starts at room temperature
  if (thermal()) {
    double *temp = field("temperature"), *inc = field("corr_increment");
    for (int i = 0; i < atom->nlocal; i++)
      if (temp[i] == 0.0) {
        temp[i] = material[atom->type[i]].t_room;
        pd_corr_increment start;
        memcpy(&start, inc + (bigint) INCREMENT * i, sizeof(start));
        start.start.temperature = temp[i];
        memcpy(inc + (bigint) INCREMENT * i, &start, sizeof(start));
      }
  }
}

PairPDCorr::Fields PairPDCorr::fields() const
{
  return {field("deformation_gradient"), field("stress"), field("corr_tensor"), field("corr_sums"),
          field("corr_shape_sums"), field("corr_shape"), field("plastic_strain"), field("plastic_tensor"),
          field("plastic_work"), field("temperature"), field("jc_damage"), field("corr_increment")};
}

// A bond's xi from the reference positions, the nearest periodic image as
// when the store built the families (at that time the box is the reference
// box; later the vector stays with the bond, through box deformation and
// restart). A bond whose xi is still zero is new.
void PairPDCorr::fill_reference_vectors()
{
  const pd_bond_view v = bonds->view();
  double *xiv = bonds->history_data();
  double **x0 = atom->x0;
  for (int i = 0; i < v.nowner; i++)
    for (int k = 0; k < v.count[i]; k++) {
      double *xi = xiv + 3 * (i * v.stride + k);
      if (xi[0] != 0.0 || xi[1] != 0.0 || xi[2] != 0.0) continue;
      const int j = v.far[i * v.stride + k];
      for (int c = 0; c < 3; c++) xi[c] = x0[j][c] - x0[i][c];
      PDCompat::minimum_image(domain, xi);
    }
}

// N = d / m of the atom's calibrated family (the influence function's
// normalization tr_w(1) = d, T14 eq. 4.5; core/pd_calibration.h)
double PairPDCorr::family_norm(int i) const
{
  const double m = calibrated_volume(i);
  return m > 0.0 ? dim() / m : 0.0;
}

pd_corr_state PairPDCorr::state(const Fields &f)
{
  pd_corr_state st = {};
  st.extended = extended;
  st.deformation = !extended || stabilization > 0.0;
  st.dim = dim();
  st.order = order;
  st.xi = bonds->history_data();
  st.tensor = f.tensor;
  st.defgrad = f.defgrad;
  st.stabilization = stabilization;
  st.spring = spring;
  st.damage = f.damage;
  st.damage_max = 0.0;
  if (damage()) {
    // D_c is one value: the smallest over the types
    st.damage_max = 1.0;
    for (int t = 1; t <= atom->ntypes; t++)
      if (setflag[t][t]) st.damage_max = MIN(st.damage_max, value(PD_CORR_DC, t, t));
  }
  return st;
}

// One owned atom: its history in, the law, its outputs and history out.
void PairPDCorr::atom_step(int i, const pd_corr_state &st, const Fields &f, const pd_corr_kinematics &kin,
                           bool with_stress, pd_tally &t)
{
  const int width = pd_corr_sums_width(&st);
  double *eqps = f.eqps, *ep = f.plastic, *wp = f.work, *temp = f.temperature, *dmg = f.damage;
  pd_corr_history h = {};
  if (ep) {
    for (int k = 0; k < 6; k++) h.plastic[k] = ep[6 * i + k];
    h.eqps = eqps[i];
    h.plastic_work = wp[i];
  }
  if (temp) h.temperature = temp[i];
  if (dmg) h.damage = dmg[i];
  const int ti = atom->type[i];
  pd_corr_atom_out o;
  pd_corr_increment inc;
  if (f.increment) memcpy(&inc, f.increment + (bigint) INCREMENT * i, sizeof(inc));
  const int ok = pd_corr_atom(&st, &material[ti], f.sums + (bigint) i * width, f.shape + (bigint) PD_CORR_SHAPE * i,
                              &kin, &h, f.increment ? &inc : nullptr, update->dt, atom->rmass[i], with_stress, &o);
  if (f.increment) memcpy(f.increment + (bigint) INCREMENT * i, &inc, sizeof(inc));
  if (ok < 0) {
    // error->one aborts the job: what this rank wrote so far must reach the log
    if (screen) fflush(screen);
    if (logfile) fflush(logfile);
    error->one(FLERR, "Pair pd/corr: atom {} (type {}) has a deformation its {} law rejects "
               "(an inverted neighbourhood, J <= 0, or a non-finite stress); a smaller timestep "
               "or 'strain extended' with m <= 0 keeps matter from inverting",
               atom->tag[i], ti, MODEL_NAMES[model]);
  }
  if (st.deformation) memcpy(f.defgrad + 9 * i, o.F, sizeof(o.F));
  if (with_stress) memcpy(f.stress + 6 * i, o.stress, sizeof(o.stress));
  memcpy(f.tensor + 9 * i, o.tensor, sizeof(o.tensor));
  if (ep) {
    for (int k = 0; k < 6; k++) ep[6 * i + k] = h.plastic[k];
    eqps[i] = h.eqps;
    // the plastic work is dissipated energy, booked with that of broken
    // bonds (compute pd/fracture, compute pd/atom dissipated)
    const double dw = h.plastic_work - wp[i];
    bonds->dissipated_atom()[i] += dw;
    bonds->fracture().add_dissipated(dw, dw * atom->vfrac[i]);
    wp[i] = h.plastic_work;
  }
  if (temp) temp[i] = h.temperature;
  if (dmg) dmg[i] = h.damage;
  if (t.eatom) t.eatom[i] += o.energy;
  t.energy += o.energy;
}

// The families' shapes, when bonds may have stopped acting since they were
// last computed: a new run, bonds broken, reneighboring (lost bonds), and
// an atom's damage past D_c (which switches its bonds off).
void PairPDCorr::update_shapes(const pd_loop &L, pd_corr_state st, const Fields &f)
{
  const int nall = atom->nlocal + atom->nghost;
  dead_at_shapes.assign(nall, 0);
  if (st.damage)
    for (int i = 0; i < nall; i++) dead_at_shapes[i] = pd_corr_past_damage(&st, i);
  const int width = extended ? PD_CORR_SHAPE_SUMS_EXTENDED : PD_CORR_SHAPE_SUMS_CLASSICAL;
  for (bigint k = 0; k < (bigint) nall * width; k++) f.shape_sums[k] = 0.0;
  st.sum = f.shape_sums;
  pd_corr_shape_sums(&L, &st);
  bonds->sum_to_owners(field_index("corr_shape_sums"));
  for (int i = 0; i < atom->nlocal; i++)
    pd_corr_shape(&st, f.shape_sums + (bigint) width * i, f.shape + (bigint) PD_CORR_SHAPE * i);
  shape_stale = false;
}

// Over every rank's owned atoms (collective): whether an atom is past D_c,
// and whether one crossed it since the shapes were computed (its owner
// sees it; the ranks then recompute the shapes together). Damage below D_c
// leaves every bond acting, so the shapes stay those of the last
// computation, to the bit.
void PairPDCorr::damage_state(const pd_corr_state &st, bool &any_dead, bool &crossed) const
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  int mine[2] = {0, (int) dead_at_shapes.size() != nall}, all[2];
  for (int i = 0; i < nlocal; i++) {
    const int dead = pd_corr_past_damage(&st, i);
    mine[0] |= dead;
    if (!mine[1]) mine[1] = dead != dead_at_shapes[i];
  }
  MPI_Allreduce(mine, all, 2, MPI_INT, MPI_MAX, world);
  any_dead = all[0] != 0;
  crossed = all[1] != 0;
}

void PairPDCorr::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (report_pending) report_setup();

  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const Fields f = fields();
  pd_corr_state st = state(f);
  // outputs only, on the steps a compute pd/atom is due: the Cauchy stress
  // (extended's takes an eigen solve per atom) and extended's F (9 of its
  // 15 sums a bond; the stress needs it too)
  const bool with_stress = demanded("stress");
  if (!st.deformation) st.deformation = demanded("deformation_gradient") || with_stress;
  const int width = pd_corr_sums_width(&st);
  // once an atom anywhere is past D_c, the damage of both ends decides
  // whether a bond counts: the same values in both passes (the owners' are
  // updated in between); before, no bond needs them (nor the ghosts' copies)
  std::vector<double> damage_used;
  bool crossed = false;
  if (damage()) {
    bool any_dead;
    damage_state(st, any_dead, crossed);
    if (any_dead) {
      bonds->forward(field_index("jc_damage"));
      damage_used.assign(st.damage, st.damage + nall);
      st.damage = damage_used.data();
    } else {
      st.damage = nullptr;
    }
  }

  Evaluation e;
  begin_evaluation(e);
  // bonds the store dropped as lost leave their families at reneighboring
  if (shape_stale || crossed || neighbor->ago == 0 || (e.fails && e.fail.replay))
    update_shapes(e.L, st, f);
  // no atom here past D_c (the shapes' flags are the current ones now):
  // every bond acts, and the loops without the damage test give the same
  // numbers
  if (st.damage && std::find(dead_at_shapes.begin(), dead_at_shapes.end(), 1) == dead_at_shapes.end())
    st.damage = nullptr;
  for (bigint k = 0; k < (bigint) nall * width; k++) f.sums[k] = 0.0;
  st.sum = f.sums;
  pd_corr_sums(&e.L, &st);
  bonds->sum_to_owners(f.sums, width);
  // the atoms' kinematics a block at a time (their frames solved side by side)
  constexpr int BLOCK = 64;
  pd_corr_kinematics kin[BLOCK];
  for (int i0 = 0; i0 < nlocal; i0 += BLOCK) {
    const int n = std::min(BLOCK, nlocal - i0);
    pd_corr_kinematics_of(&st, n, f.sums + (bigint) i0 * width, f.shape + (bigint) PD_CORR_SHAPE * i0, kin);
    for (int k = 0; k < n; k++) atom_step(i0 + k, st, f, kin[k], with_stress, e.tally);
  }

  for (const PDField &decl : declared)
    if (decl.flags & PDField::FORWARD && decl.name != "jc_damage") bonds->forward(field_index(decl.name));
  pd_corr_forces(&e.L, &st);
  // bonds that broke leave their families: new shapes next time
  if (end_evaluation(e)) shape_stale = true;
}

// As the ordinary solid of the same moduli (pd_ordinary_stiffness): an
// estimate of the bond stiffness, N (2 mu_bar + d |lambda_bar|) per atom
// (owned + ghost), in the pair's scratch.
double *PairPDCorr::stiffness_coefficients()
{
  double *k = scratch();
  for (int i = 0; i < atom->nlocal; i++) {
    const int ti = atom->type[i];
    pd_elastic m;
    pd_elastic_from_K_G(value(PD_CORR_K, ti, ti), value(PD_CORR_G, ti, ti), &m);
    const pd_lame l = pd_ordinary_lame(model_dim, &m);
    const double wv = bonds->weighted_volume()[i];
    k[i] = wv > 0.0 ? dim() / wv * (2.0 * l.mu + dim() * fabs(l.lambda)) : 0.0;
  }
  bonds->copy_to_ghosts(k);
  return k;
}

void PairPDCorr::stable_dt_sum(double *sum)
{
  const double *k = stiffness_coefficients();
  const pd_bond_view v = bonds->view();
  pd_ordinary_stiffness(&v, k, atom->vfrac, sum);
}

// The same scaled by the current rate of the bond strain (no stress
// terms: the correspondence stress is a tensor, not a bond's)
void PairPDCorr::tangent_sum(double *sum, double *closing)
{
  const pd_state_tangent ctx = {order, stiffness_coefficients(), nullptr};
  Evaluation e;
  begin_pass(e);
  pd_state_tangent_sums(&e.L, atom->v[0], &ctx, sum, closing);
}

void PairPDCorr::report_extra()
{
  std::string fields;
  for (const PDField &f : per_atom_fields())
    if (f.flags & (PDField::OUTPUT | PDField::RESTART)) fields += " " + f.name;
  utils::logmesg(lmp, "pd/corr: {} correspondence{}, model {}, strain order m = {}, influence {}; "
                 "per-atom fields:{}\n", extended ? "extended (T14 4.2)" : "classical (T14 2.2.1)",
                 stabilization > 0.0 ? fmt::format(" with stabilization {}", stabilization) : "",
                 MODEL_NAMES[model], order, pd_influence_name((pd_influence_kind) influence), fields);
  // the penalty has no energy of its own: pe + ke stops being conserved
  if (stabilization > 0.0)
    error->warning(FLERR, "Pair pd/corr: stabilization {} is a penalty force without an energy: kinetic "
                   "+ potential energy is not conserved (an energy balance drifts); use it to keep "
                   "zero-energy modes down, not where the energy budget matters", stabilization);
}

void PairPDCorr::restart_settings(PDSettingsIO &io)
{
  PairPD::restart_settings(io);
  io(extended);
  io(model);
  io(influence);
  io(stabilization);
}

// The PMB micromodulus of the same Young's modulus (contact, broken bonds,
// stabilization).
double PairPDCorr::contact_micromodulus(int i, int j) const
{
  const double E = 0.5 * (coef[PD_CORR_E][i][i] + coef[PD_CORR_E][j][j]);
  return pd_pmb_micromodulus(model_dim, E, horizon(i, j), thickness);
}
