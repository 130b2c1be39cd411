/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: the declared per-atom fields of fix pd/bonds.

   A field is declared once by whoever needs it (the store for its own
   data, a pair style at init for its per-atom state): a name, a width and
   flags (pd_field.h). The store keeps 'width' doubles per atom over owned
   and ghost atoms, grows them with the atoms, copies them to ghosts and
   sums or maxes them onto owners on request, and carries the MIGRATE
   fields in exchange records and the RESTART fields in restart records
   (both after the count and own tag, before the bonds). The global restart
   record lists the RESTART fields by name and width, in the order of the
   per-atom records, so that reading a file finds each field by name and a
   width that does not match is an ERROR that names the field.
------------------------------------------------------------------------- */

#include "fix_pd_bonds.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "pd_bonds_record.h"
#include "pd_compat.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace {
enum { COPY_TO_GHOSTS, SUM_TO_OWNERS, MAX_TO_OWNERS };
constexpr int MIN_COMM_WIDTH = 3;        // the width the array helpers always allow (velocities)
constexpr int MAX_NAME = 256;            // a field name in a restart file, in bytes
constexpr int MAX_FILE_FIELDS = 1000;    // fields a restart file may list
constexpr int MAX_WIDTH = 100000;        // doubles per atom of one field
}    // namespace

std::vector<PDField> FixPDBonds::own_fields()
{
  const int kept = PDField::MIGRATE | PDField::RESTART | PDField::OUTPUT;
  return {{"dissipated", 1, kept},
          {"family_volume", 1, kept},
          {"weighted_volume", 1, kept},
          {"build_volume", 1, PDField::MIGRATE | PDField::RESTART}};
}

int FixPDBonds::find_field(const std::string &name) const
{
  for (size_t id = 0; id < fields.size(); id++)
    if (fields[id].decl.name == name) return (int) id;
  return -1;
}

int FixPDBonds::add_field(const PDField &decl)
{
  if (decl.name.empty() || (int) decl.name.size() > MAX_NAME || decl.width < 1 || decl.width > MAX_WIDTH)
    error->all(FLERR, "Fix pd/bonds: per-atom field '{}' of width {}: a field needs a name of 1 to {} "
               "characters and a width of 1 to {}", decl.name, decl.width, MAX_NAME, MAX_WIDTH);
  int id = find_field(decl.name);
  if (id >= 0) {
    Field &f = fields[id];
    if (f.decl.width != decl.width)
      error->all(FLERR, "Fix pd/bonds: per-atom field '{}' has width {} {}, {} now", decl.name,
                 f.decl.width, f.provisional ? "in the restart file" : "as first declared", decl.width);
    if (!f.provisional && f.decl.flags != decl.flags)
      error->all(FLERR, "Fix pd/bonds: per-atom field '{}' declared again with other flags ({}, first {})",
                 decl.name, decl.flags, f.decl.flags);
    // a field read from a restart file takes the flags of its declaration
    f.decl.flags = decl.flags;
    f.provisional = false;
  } else {
    // state that a restart file should have carried would start from zero
    if (fields_from_file && built && (decl.flags & PDField::RESTART))
      error->all(FLERR, "Fix pd/bonds: the restart file carries no per-atom field '{}' (width {}), which "
                 "the pair style keeps in restart files: the file was written with another pair "
                 "style or by another build", decl.name, decl.width);
    Field f = {decl, nullptr, false};
    const bigint n = (bigint) atom->nmax * decl.width;
    if (n > MAXSMALLINT) error->all(FLERR, "Fix pd/bonds: per-atom field '{}' is too large", decl.name);
    if (n > 0) {
      memory->create(f.data, (int) n, "pd/bonds:field");
      for (bigint k = 0; k < n; k++) f.data[k] = 0.0;
    }
    fields.push_back(f);
    id = (int) fields.size() - 1;
  }
  // communication and exchange buffers are sized from these when the run
  // is set up (after the pair styles' init, where fields are declared)
  int widest = MIN_COMM_WIDTH;
  for (const Field &f : fields) widest = MAX(widest, f.decl.width);
  comm_forward = comm_reverse = widest;
  maxexchange = per_atom_max(PDField::MIGRATE);
  return id;
}

void FixPDBonds::grow_fields(int nmax)
{
  for (Field &f : fields) {
    const bigint n = (bigint) nmax * f.decl.width;
    if (n > MAXSMALLINT) error->one(FLERR, "Fix pd/bonds: per-atom field '{}' is too large", f.decl.name);
    memory->grow(f.data, (int) n, "pd/bonds:field");
  }
}

int FixPDBonds::field_doubles(int flag) const
{
  int n = 0;
  for (const Field &f : fields)
    if (f.decl.flags & flag) n += f.decl.width;
  return n;
}

// Atom i's values of the fields with 'flag', in declaration order.
int FixPDBonds::pack_fields(int i, double *buf, int flag) const
{
  int m = 0;
  for (const Field &f : fields)
    if (f.decl.flags & flag)
      for (int w = 0; w < f.decl.width; w++) buf[m++] = f.data[i * f.decl.width + w];
  return m;
}

// The inverse of pack_fields for a migrating atom (MIGRATE), or for an atom
// of a restart file (RESTART: the fields in the order the file lists
// them). The atom's other fields start from zero.
int FixPDBonds::unpack_fields(int i, const double *buf, int flag)
{
  for (Field &f : fields)
    for (int w = 0; w < f.decl.width; w++) f.data[i * f.decl.width + w] = 0.0;
  int m = 0;
  const auto take = [&](Field &f) {
    for (int w = 0; w < f.decl.width; w++) f.data[i * f.decl.width + w] = buf[m++];
  };
  if (flag == PDField::RESTART)
    for (int id : restart_read) take(fields[id]);
  else
    for (Field &f : fields)
      if (f.decl.flags & flag) take(f);
  return m;
}

// The RESTART fields in the global restart record: their count, then for
// each its width, flags and name.
void FixPDBonds::append_field_list(PDRecordWriter &out) const
{
  std::vector<const Field *> written;
  for (const Field &f : fields)
    if (f.decl.flags & PDField::RESTART) written.push_back(&f);
  out.put((int64_t) written.size());
  for (const Field *f : written) {
    out.put((int64_t) f->decl.width);
    out.put((int64_t) f->decl.flags);
    out.put_string(f->decl.name);
  }
}

// The field list of a restart file, read without acting on it (the
// record's checksum is verified first): false when it is damaged.
bool FixPDBonds::read_field_list(PDRecordReader &in, std::vector<PDField> &list)
{
  int64_t n = -1;
  if (!in.get(n) || n < 0 || n > MAX_FILE_FIELDS) return false;
  list.clear();
  for (int64_t k = 0; k < n; k++) {
    int64_t width = 0, flags = -1;
    std::string name;
    if (!in.get(width) || !in.get(flags) || !in.get_string(name)) return false;
    if (width < 1 || width > MAX_WIDTH || flags < 0 || flags >= 256 || name.empty() ||
        (int) name.size() > MAX_NAME)
      return false;
    for (const PDField &seen : list)
      if (seen.name == name) return false;
    list.push_back({name, (int) width, (int) flags});
  }
  return true;
}

// Each field of the file's list is found by name (one not declared yet is
// kept with the file's width until its owner declares it), and sets the
// layout of the per-atom records that follow.
void FixPDBonds::take_field_list(const std::vector<PDField> &list)
{
  restart_read.clear();
  for (const PDField &file : list) {
    int id = find_field(file.name);
    if (id >= 0 && fields[id].decl.width != file.width)
      error->all(FLERR, "Fix pd/bonds: per-atom field '{}' has width {} in the restart file, {} in "
                 "this build: the file cannot be read by it", file.name, file.width, fields[id].decl.width);
    if (id < 0) {
      id = add_field({file.name, file.width, file.flags | PDField::RESTART});
      fields[id].provisional = true;
    }
    restart_read.push_back(id);
  }
  for (size_t id = 0; id < fields.size(); id++) {
    bool listed = false;
    for (int r : restart_read) listed = listed || r == (int) id;
    if ((fields[id].decl.flags & PDField::RESTART) && !listed)
      error->all(FLERR, "Fix pd/bonds: the restart file carries no per-atom field '{}' (width {}): it "
                 "was written by another build", fields[id].decl.name, fields[id].decl.width);
  }
  fields_from_file = true;
}

// A field of the restart file that no one declared by the set-up of the
// run (pair styles, fixes and computes declare theirs at init) is state the
// run would drop: the plastic strain of a J2 file continued with the
// elastic model.
void FixPDBonds::check_fields_claimed() const
{
  for (const Field &f : fields)
    if (f.provisional)
      error->all(FLERR, "Fix pd/bonds: the restart file carries per-atom field '{}' (width {}), which "
                 "pair style {} does not keep: the file was written with another pair style, model "
                 "or failure law, and the run would drop that state; continue with the pair_style "
                 "and pair_coeff that wrote it", f.decl.name, f.decl.width, spec.style);
}

/* ---------------------------------------------------------------------- */

void FixPDBonds::forward(int id)
{
  communicate(fields[id].data, fields[id].decl.width, COPY_TO_GHOSTS);
}

void FixPDBonds::sum_to_owners(int id)
{
  communicate(fields[id].data, fields[id].decl.width, SUM_TO_OWNERS);
}

void FixPDBonds::max_to_owners(int id)
{
  communicate(fields[id].data, fields[id].decl.width, MAX_TO_OWNERS);
}

void FixPDBonds::copy_to_ghosts(double *a, int width)
{
  communicate(a, width, COPY_TO_GHOSTS);
}

void FixPDBonds::sum_to_owners(double *a, int width)
{
  communicate(a, width, SUM_TO_OWNERS);
}

void FixPDBonds::max_to_owners(double *a, int width)
{
  communicate(a, width, MAX_TO_OWNERS);
}

// LAMMPS sizes its buffers for comm_forward / comm_reverse doubles per atom
// when a run is set up: the widest declared field, at least MIN_COMM_WIDTH.
// A wider array goes in slices of that many columns, one exchange each (a
// set-up's scratch, which a field would keep, and buffers sized for it,
// for the whole run).
void FixPDBonds::communicate(double *a, int width, int how)
{
  if (width < 1) error->all(FLERR, "Fix pd/bonds: a per-atom array of width {} (a bug)", width);
  if (width > comm_forward) {
    const int nall = atom->nlocal + atom->nghost;
    std::vector<double> slice((size_t) nall * comm_forward);
    for (int first = 0; first < width; first += comm_forward) {
      const int w = MIN(comm_forward, width - first);
      for (int i = 0; i < nall; i++)
        for (int c = 0; c < w; c++) slice[(size_t) i * w + c] = a[(size_t) i * width + first + c];
      communicate(slice.data(), w, how);
      for (int i = 0; i < nall; i++)
        for (int c = 0; c < w; c++) a[(size_t) i * width + first + c] = slice[(size_t) i * w + c];
    }
    return;
  }
  comm_array = a;
  comm_width = width;
  comm_max = how == MAX_TO_OWNERS;
  if (how == COPY_TO_GHOSTS) PDCompat::forward_comm(comm, this, width);
  else PDCompat::reverse_comm(comm, this, width);
  comm_max = 0;
}
