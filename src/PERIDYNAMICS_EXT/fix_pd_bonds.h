/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: the bond families of the pd/ pair styles.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(pd/bonds,FixPDBonds);
// clang-format on
#else

#ifndef LMP_FIX_PD_BONDS_H
#define LMP_FIX_PD_BONDS_H

#include "fix.h"
#include "pd_field.h"

#include "pd_family_spec.h"
#include "pd_fracture_record.h"

#include <functional>
#include <string>
#include <vector>

extern "C" {
#include "pd_bonds.h"
#include "pd_precrack.h"
}

namespace LAMMPS_NS {

class FixPDBonds : public Fix {
 public:
  FixPDBonds(class LAMMPS *, int, char **);
  ~FixPDBonds() override;
  int setmask() override;
  void init() override;
  void setup_post_neighbor() override;
  void post_neighbor() override;
  void min_post_neighbor() override { post_neighbor(); }
  void pre_exchange() override;
  void post_run() override;
  void setup(int) override;
  void end_of_step() override;
  double compute_scalar() override;
  double memory_usage() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  void write_data_header(FILE *, int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  // the families exist (built once, kept by restart)
  bool is_built() const { return built; }
  // what each bond carries: a weight, and how many history values
  bool carries_weights() const { return use_weights; }
  int history_count() const { return nhistory; }
  pd_bond_view view() const;
  // the bonds as plain rows (the fracture record's replay reads and signs them)
  PDBondTable table() const;
  // per-bond history values (nhistory per bond, laid out as the bonds), or null
  double *history_data() const { return nhistory && history ? history[0] : nullptr; }
  double bytes_per_bond() const;
  // broken bonds: the sign of the reference length (pd_failure.h)
  double *len0_data() const { return r0 ? r0[0] : nullptr; }
  // what the bonds' failure has done (broken counts, dissipated energy) and
  // the fresh-bond replay (pd_fracture_record.h); kept in restart files
  PDFractureRecord &fracture() { return record; }
  const PDFractureRecord &fracture() const { return record; }
  bigint local_lost() const { return nlost_local; }
  // Every bond (broken or not) in the reference configuration: owner i,
  // far end j (local or ghost), reference vector xi = x0_j - x0_i, weight.
  void each_reference_bond(const std::function<void(int, int, const double *, double)> &visit) const;
  // The weights as the family spec gave them at the build, before anyone
  // scaled them (false for families from a restart file: scaled already).
  bool weights_as_built() const { return weights_fresh; }
  // Multiplies every bond's weight by factor(i, j, xi) once, and the
  // reference sums (weighted volumes) follow.
  void scale_weights(const std::function<double(int, int, const double *)> &factor);
  // the stable time step estimate of this run, for the blow-up guard's message
  void note_stable_dt(double dt) { stable_dt = dt; }

  // Break the intact bonds (both ends in the group) whose reference segment
  // crosses the crack; returns how many, over all ranks.
  bigint cut_crossing(const pd_crack &crack, int groupbit);
  // A crack of fix 'fixid' known before the families exist: a restart file
  // written before the first run carries it, and the families built from
  // that file are cut by it.
  void remember_cut(const std::string &fixid, const pd_crack &crack, int groupbit);

  // Declared per-atom fields (pd_field.h). add_field() returns the field's
  // id; declaring a name again returns the same id (width and flags must
  // agree). Declare at init (a pair style's init_style), before the run's
  // set-up sizes the communication buffers. field(id) is the storage, owned
  // + ghost atoms, atom i at [i * width]; it moves when atoms are added, so
  // take it again after reneighboring rather than keeping it.
  int add_field(const PDField &decl);
  int find_field(const std::string &name) const;    // -1: none of that name
  int nfields() const { return (int) fields.size(); }
  const PDField &field_info(int id) const { return fields[id].decl; }
  double *field(int id) const { return fields[id].data; }
  void forward(int id);          // owners' values to their ghosts
  void sum_to_owners(int id);    // ghosts' values added onto their owners
  void max_to_owners(int id);    // owners take the max of theirs and their ghosts'
  // the store's own fields, declared whether or not a store exists yet
  static std::vector<PDField> own_fields();
  // per-atom energy dissipated in the bonds (plastic work, fracture), as an
  // energy density; and the reference family data fixed when the families
  // are built: sum of the partners' volumes, sum of weight x partner volume
  double *dissipated_atom() const { return field(idissipated); }
  double *family_volume() const { return field(ifamily_volume); }
  double *weighted_volume() const { return field(iweighted_volume); }

  // The same for a per-atom array that is not a field ('width' doubles per
  // atom; wider than the widest declared field, at least 3, it goes in
  // slices of that width, one exchange each).
  void sum_to_owners(double *a, int width = 1);
  void max_to_owners(double *a, int width = 1);
  void copy_to_ghosts(double *a, int width = 1);

 private:
  // the families of this run's material (copied at init from the pair style
  // that provides them); 'serving' is false in a run without one
  PDFamilySpec spec;
  bool serving;
  tagint *built_tag;       // each atom's own tag when the families were built (0: none)
  int use_weights;         // 1 if bonds carry a quadrature weight
  int nhistory;            // history values per bond (e.g. plastic stretch)
  int built;               // families exist (set once, kept by restart)
  bool weights_fresh;      // weights as built, not scaled yet (weights_as_built)
  int maxpartner;          // row length of the per-atom bond tables
  int nrows;               // rows of the bond tables: owned atoms only (see grow_rows)
  int nowned;              // atoms whose local indices are current
  int *npartner;           // bonds owned by each atom
  tagint **partner;        // far end of each bond, as a global tag
  double **r0;             // reference length
  double **weight;         // quadrature weight (use_weights only)
  double **history;        // per-bond history (nhistory > 0 only)
  int **far;               // far end as a local index (owned+ghost)
  bigint nlost_local;      // intact bonds lost (counted on rank 0)
  bigint intact_at_map;    // intact bonds over all ranks at the last mapping (-1: none yet)
  bigint stored_total;     // bonds stored over all ranks at the last mapping
  bigint nlost_reported;   // the global count last warned about
  int warned_images;       // the periodic-image warning was given this run
  double family_key;       // PDFamilySpec::key of the settings the families were built for
  PDFractureRecord record; // broken counts, dissipated energy, fresh-bond replay
  double stable_dt;        // this run's stable time step estimate (0: not known)
  struct PendingCut {
    std::string fixid;    // the pd/precrack fix of this run ("" when read from a restart file)
    pd_crack crack;
    int groupbit;
  };
  std::vector<PendingCut> pending_cuts;
  double *comm_array;
  int comm_width;
  int comm_max;            // reverse comm takes the max instead of the sum

  // the declared per-atom fields (fix_pd_bonds_fields.cpp)
  struct Field {
    PDField decl;
    double *data;          // nmax x width
    bool provisional;      // known only from a restart file so far: flags taken from the file
  };
  std::vector<Field> fields;
  int idissipated, ifamily_volume, iweighted_volume, ibuild_volume;
  std::vector<int> restart_read;    // the fields of the per-atom restart records being read, in the file's order
  bool fields_from_file;            // the store was read from a restart file
  int field_doubles(int flag) const;    // per atom, over the fields with that flag
  void grow_fields(int nmax);
  int pack_fields(int i, double *buf, int flag) const;
  int pack_atom(int i, double *buf, int flag) const;
  int unpack_atom(int i, const double *buf, int flag);
  int unpack_fields(int i, const double *buf, int flag);
  void append_field_list(class PDRecordWriter &out) const;
  static bool read_field_list(class PDRecordReader &in, std::vector<PDField> &list);
  void take_field_list(const std::vector<PDField> &list);
  void check_fields_claimed() const;
  void communicate(double *a, int width, int how);

  void take_family_spec();
  void build_families();
  void map_partners(bool setup, bool built = false);
  void check_stored_partners(bool scan_bonds);
  bigint count_lost(bigint stored, bigint intact);
  void warn_ambiguous_images(bigint mine);
  void report_bonds_by_type(const std::vector<bigint> &touching);
  // the blow-up guard (fix_pd_bonds_guard.cpp)
  double guard_step;        // the largest distance an atom may move in one step
  double guard_ke;          // kinetic energy at setup or at the last growth check
  bigint guard_ke_step;     // and its step
  bigint guard_window;      // steps the last growth took (0: none yet)
  int guard_streak;         // growths in a row that took no longer than the one before
  bool guard_relaxing;      // a pseudo-time relaxation (fix pd/adr): no energy check
  void guard(bool forces_only);
  static bool guard_screen(const double *f, const double *v, const double *mass, const double *volume,
                           int n, double vmax2, double &mv2);
  void guard_drift(double *vc);
  std::string guard_energy(double ke);
  std::string blow_up(int i, const char *what, double value);
  Fix *relaxation() const;
  bigint damaged;           // stored bond records found damaged (restart, exchange)
  bigint damaged_example;   // the count one of them claimed
  void check_identities();
  void check_volumes();
  void reference_sums();
  void reference_vector(int i, int k, double xi[3]) const;
  void remove_bond(int i, int k);
  void resize_tables(int rowlength);
  void shorten_rows(int rowlength);
  void grow_rows(int n);
  void destroy_tables();
  void ensure_row(int i) { if (i >= nrows) grow_rows(i + 1); }
  int per_atom_doubles(int i, int flag) const;
  int per_atom_max(int flag) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
