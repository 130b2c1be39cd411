/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/atom: the declared per-atom fields of the
   bond store by name (fix pd/bonds: its own and the pair style's), the
   pair style's energy density, and a dilatation from the bonds for styles
   that declare none; in the order given, a field of width w as w columns.
------------------------------------------------------------------------- */

#include "compute_pd_atom.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "force.h"
#include "memory.h"
#include "pair.h"
#include "pair_pd.h"
#include "pd_compat.h"
#include "pd_modify_lookup.h"
#include "update.h"

#include <cstring>

extern "C" {
#include "pd_ordinary.h"
}

using namespace LAMMPS_NS;

ComputePDAtom::ComputePDAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), ncols(0), nmax(0), scratch(nullptr), vector(nullptr), array(nullptr),
    bonds(nullptr)
{
  const std::vector<PDField> known = known_fields();
  if (narg < 4)
    error->all(FLERR, "Illegal compute pd/atom command: name at least one field ({})", available(known));
  for (int iarg = 3; iarg < narg; iarg++) {
    const std::string name = arg[iarg];
    Output o = {name, FIELD, 0, -1, false};
    for (const PDField &f : known)
      if (f.name == name) o.width = f.width;
    if (name == "energy") {
      o.source = ENERGY;
      o.width = 1;
      peatomflag = 1;    // the integrator then tallies per-atom energy when we are invoked
      timeflag = 1;
    } else if (name == "dilatation" && !o.width) {
      o.source = BOND_DILATATION;
      o.width = 1;
    } else if (!o.width) {
      error->all(FLERR, "Compute pd/atom: unknown field '{}'; available: {}", name, available(known));
    }
    outputs.push_back(o);
    ncols += o.width;
  }
  peratom_flag = 1;
  size_peratom_cols = outputs.size() == 1 && ncols == 1 ? 0 : ncols;
}

ComputePDAtom::~ComputePDAtom()
{
  memory->destroy(scratch);
  memory->destroy(vector);
  memory->destroy(array);
}

bool ComputePDAtom::lists(const std::string &name) const
{
  for (const Output &o : outputs)
    if (o.name == name) return true;
  return false;
}

// The output fields known now: the bond store's (its own, and those the
// pair style declared) or, before the store exists, its own and those the
// current pair style will declare.
std::vector<PDField> ComputePDAtom::known_fields() const
{
  std::vector<PDField> all;
  auto *store = dynamic_cast<FixPDBonds *>(PDCompat::fix_by_id(modify, "PD_BONDS"));
  if (store)
    for (int id = 0; id < store->nfields(); id++) all.push_back(store->field_info(id));
  else
    all = FixPDBonds::own_fields();
  if (PairPD *pair = PairPD::active(force))
    for (const PDField &f : pair->fields_to_declare()) {
      bool listed = false;
      for (const PDField &g : all) listed = listed || g.name == f.name;
      if (!listed) all.push_back(f);
    }
  std::vector<PDField> out;
  for (const PDField &f : all)
    if (f.flags & PDField::OUTPUT) out.push_back(f);
  return out;
}

std::string ComputePDAtom::available(const std::vector<PDField> &known) const
{
  std::string s = "energy";
  bool dilatation = false;
  for (const PDField &f : known) {
    s += f.width == 1 ? fmt::format(", {}", f.name) : fmt::format(", {} ({} columns)", f.name, f.width);
    dilatation = dilatation || f.name == "dilatation";
  }
  if (!dilatation) s += ", dilatation";
  if (!PairPD::active(force)) s += "; a pd/ pair style defined before this compute adds its own";
  return s;
}

// The fields by name in the bond store, as the pair style declared them at
// its init; the dilatation is the style's own when it declares one.
void ComputePDAtom::init()
{
  bonds = find_bond_store(lmp, "compute pd/atom");
  for (Output &o : outputs) {
    if (o.source == ENERGY) continue;
    const int id = bonds->find_field(o.name);
    const bool output = id >= 0 && (bonds->field_info(id).flags & PDField::OUTPUT);
    if (o.name == "dilatation") {
      o.source = output && bonds->field_info(id).width == 1 ? FIELD : BOND_DILATATION;
      o.id = o.source == FIELD ? id : -1;
      continue;
    }
    if (!output) {
      std::vector<PDField> known;
      for (int f = 0; f < bonds->nfields(); f++)
        if (bonds->field_info(f).flags & PDField::OUTPUT) known.push_back(bonds->field_info(f));
      error->all(FLERR, "Compute pd/atom: the pair style keeps no field '{}' in this run; available: {}",
                 o.name, available(known));
    }
    if (bonds->field_info(id).width != o.width)
      error->all(FLERR, "Compute pd/atom: field '{}' now has {} columns, {} when the compute was defined",
                 o.name, bonds->field_info(id).width, o.width);
    o.id = id;
    // as the style declares it for this run; the pair style computes it on
    // the steps LAMMPS has this compute due (its schedule, kept with timeflag)
    o.on_demand = (bonds->field_info(id).flags & PDField::ON_DEMAND) != 0;
    if (o.on_demand) timeflag = 1;
  }
}

void ComputePDAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(scratch);
    memory->create(scratch, nmax, "pd/atom:scratch");
    if (size_peratom_cols == 0) {
      memory->destroy(vector);
      memory->create(vector, nmax, "pd/atom:vector");
      vector_atom = vector;
    } else {
      memory->destroy(array);
      memory->create(array, nmax, size_peratom_cols, "pd/atom:array");
      array_atom = array;
    }
  }
  const int nlocal = atom->nlocal, *mask = atom->mask;
  int col = 0;
  for (const Output &o : outputs) {
    if (o.on_demand) current_or_error(o.name);
    const double *values = scratch;
    if (o.source == FIELD) values = bonds->field(o.id);
    else if (o.source == BOND_DILATATION) dilatation(scratch);
    else energy_density(scratch);
    for (int i = 0; i < nlocal; i++)
      for (int w = 0; w < o.width; w++) {
        const double v = (mask[i] & groupbit) ? values[i * o.width + w] : 0.0;
        if (size_peratom_cols == 0) vector[i] = v;
        else array[i][col + w] = v;
      }
    col += o.width;
  }
}

// An ON_DEMAND field is this step's only when the pair style computed it
// now: when LAMMPS had this compute due (a dump, thermo or fix output
// invokes it), not when a variable reads it between those.
void ComputePDAtom::current_or_error(const std::string &name) const
{
  PairPD *pair = PairPD::active(force);
  const bigint on = pair ? pair->computed_on(name) : -1;
  if (on != update->ntimestep)
    error->all(FLERR, "Compute pd/atom: field '{}' is computed on the steps this compute is due (by a "
               "dump, thermo or fix output that uses it) and at each run's start; step {} is none "
               "(last computed on step {}): use it from such an output, or 'run 0' first",
               name, update->ntimestep, on);
}

// The dilatation when no style declares one (pd/bond): theta = d / m sum
// w s V, the linear dilatation with the bond weights and weighted volume
// (for pd/bond, whose bonds carry no weight, m = sum V).
void ComputePDAtom::dilatation(double *out)
{
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) out[i] = 0.0;
  const double *weighted = bonds->weighted_volume();
  const pd_bond_view v = bonds->view();
  pd_ordinary_state st = {0.5, out, nullptr, nullptr, 0};
  pd_failure intact_only = {};    // broken bonds stretch freely: they do not count
  intact_only.recontact = 0;
  const pd_loop L = {&v, atom->type, atom->ntypes + 1, atom->x[0], atom->vfrac, nullptr, nullptr, &intact_only,
                     nullptr, 0};
  pd_ordinary_dilatation(&L, &st);
  bonds->sum_to_owners(out);
  for (int i = 0; i < atom->nlocal; i++) {
    const double m = weighted[i];
    out[i] = m > 0.0 ? domain->dimension * out[i] / m : 0.0;
  }
}

// The pair style's per-atom energy density (owned + ghost shares summed).
void ComputePDAtom::energy_density(double *out)
{
  if (update->eflag_atom != invoked_peratom)
    error->all(FLERR, "Compute pd/atom energy: per-atom energy was not tallied on this timestep "
               "(use it on thermo or dump steps)");
  const int nall = atom->nlocal + atom->nghost;
  double *eatom = force->pair ? force->pair->eatom : nullptr;
  for (int i = 0; i < nall; i++) out[i] = eatom ? eatom[i] : 0.0;
  bonds->sum_to_owners(out);
}

double ComputePDAtom::memory_usage()
{
  return (double) nmax * (1 + ncols) * sizeof(double);
}
