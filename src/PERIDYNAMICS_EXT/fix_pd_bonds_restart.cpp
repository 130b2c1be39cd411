/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: the global restart record of fix pd/bonds.

   The record is declared in pd_bonds_record.h: a fixed struct (tag,
   version, sizes, named fields) followed by variable-length lists, in
   this order:
     1. the bonds broken at the last evaluation (the fresh-bond replay of
        the fracture record; every rank has them all) and their lengths,
     2. the cracks waiting for the families (pre-cracks of a restart file
        written before the first run),
     3. the declared per-atom fields written in the per-atom records (their
        count, then width, flags and name of each), in the records' order.
   The per-atom bond data are written by pack_restart (fix_pd_bonds.cpp).
------------------------------------------------------------------------- */

#include "fix_pd_bonds.h"

#include "comm.h"
#include "error.h"
#include "pd_bonds_record.h"
#include "pd_compat.h"

#include <cmath>
#include <cstddef>
#include <cstring>

using namespace LAMMPS_NS;

void FixPDBonds::write_restart(FILE *fp)
{
  bigint total_lost = 0;
  MPI_Allreduce(&nlost_local, &total_lost, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  const PDFractureRecord::Totals totals = record.sum_over_ranks();
  if (comm->me != 0) return;
  std::vector<const PendingCut *> cuts;
  for (const PendingCut &c : pending_cuts)
    if (!built && (c.fixid.empty() || PDCompat::fix_by_id(modify, c.fixid))) cuts.push_back(&c);
  const std::vector<tagint> &fresh_pairs = record.fresh_pairs();
  const std::vector<double> &fresh_lengths = record.fresh_lengths();

  PDBondsRecord r;
  memset(&r, 0, sizeof r);
  memcpy(r.tag, PD_BONDS_RECORD_TAG, sizeof r.tag);
  r.version = PD_BONDS_RECORD_VERSION;
  r.fixed_bytes = sizeof r;
  r.built = built;
  r.maxpartner = maxpartner;
  r.weights = use_weights;
  r.history = nhistory;
  r.family_key = family_key;
  r.lost = total_lost;
  r.intact_at_map = intact_at_map;
  r.broken = totals.broken;
  r.breaks_since_map = totals.breaks_since_map;
  r.dissipated = totals.dissipated;
  r.dissipated_joule = totals.dissipated_joule;
  r.any_broken = totals.any_broken;
  r.fresh_step = totals.fresh_step;
  r.nfresh = fresh_lengths.size();
  r.ncuts = cuts.size();

  PDRecordWriter lists;
  for (size_t p = 0; p < fresh_lengths.size(); p++) {
    lists.put((int64_t) fresh_pairs[2 * p]);
    lists.put((int64_t) fresh_pairs[2 * p + 1]);
    lists.put(fresh_lengths[p]);
  }
  for (const PendingCut *c : cuts) {
    lists.put((int64_t) c->crack.patch);
    for (const double *v : {c->crack.a, c->crack.b, c->crack.c})
      for (int d = 0; d < 3; d++) lists.put(v[d]);
    lists.put((int64_t) c->groupbit);
  }
  // the per-atom fields of the per-atom records, by name (fix_pd_bonds_fields.cpp)
  append_field_list(lists);

  r.total_bytes = sizeof r + lists.bytes.size();
  r.checksum = 0;
  r.checksum = (int64_t) pd_record_checksum(lists.bytes.data(), lists.bytes.size(),
                                            pd_record_checksum(&r, sizeof r));
  const int size = (int) r.total_bytes;
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(&r, sizeof r, 1, fp);
  fwrite(lists.bytes.data(), 1, lists.bytes.size(), fp);
}

// Tag, version and size are checked before any field is read: a record of
// another version is refused by name, not misread.
void FixPDBonds::restart(char *buf)
{
  if (memcmp(buf, PD_BONDS_RECORD_TAG, sizeof PD_BONDS_RECORD_TAG) != 0) {
    double old_tag;
    memcpy(&old_tag, buf, sizeof old_tag);
    error->all(FLERR, "Fix pd/bonds: the restart file's bond record is in an older format (format "
               "tag {}, before versioned records); this build reads bond record version {}: "
               "continue with the PERIDYNAMICS_EXT build that wrote the file, or start again",
               old_tag, PD_BONDS_RECORD_VERSION);
  }
  int64_t version, fixed_bytes;
  memcpy(&version, buf + offsetof(PDBondsRecord, version), sizeof version);
  memcpy(&fixed_bytes, buf + offsetof(PDBondsRecord, fixed_bytes), sizeof fixed_bytes);
  if (version != PD_BONDS_RECORD_VERSION)
    error->all(FLERR, "Fix pd/bonds: the restart file's bond record is version {}; this build reads "
               "version {} (the file was written by {} PERIDYNAMICS_EXT)", version,
               PD_BONDS_RECORD_VERSION, version < PD_BONDS_RECORD_VERSION ? "an older" : "a newer");
  if (fixed_bytes != (int64_t) sizeof(PDBondsRecord))
    error->all(FLERR, "Fix pd/bonds: the restart file's bond record (version {}) has a fixed part "
               "of {} bytes; this build expects {} bytes for version {}: the file is damaged or "
               "was written by a build with another layout", version, fixed_bytes,
               sizeof(PDBondsRecord), PD_BONDS_RECORD_VERSION);
  PDBondsRecord r;
  memcpy(&r, buf, sizeof r);

  const bool sane = (r.built == 0 || r.built == 1) && r.maxpartner >= 1 && r.maxpartner <= 1000000 &&
      r.nfresh >= 0 && r.nfresh <= 1000000000 && r.ncuts >= 0 && r.ncuts <= 1000000 && r.lost >= 0 &&
      r.broken >= 0 && std::isfinite(r.dissipated) && std::isfinite(r.dissipated_joule) &&
      r.total_bytes >= (int64_t) sizeof r && r.total_bytes <= INT32_MAX;
  std::vector<tagint> fresh_pairs;
  std::vector<double> fresh_lengths;
  std::vector<PendingCut> cuts;
  std::vector<PDField> file_fields;
  bool complete = sane;
  if (sane) {
    PDRecordReader in(buf + sizeof r, r.total_bytes - sizeof r);
    for (int64_t p = 0; p < r.nfresh && complete; p++) {
      int64_t owner, other;
      double length = 0.0;
      complete = in.get(owner) && in.get(other) && in.get(length);
      fresh_pairs.push_back((tagint) owner);
      fresh_pairs.push_back((tagint) other);
      fresh_lengths.push_back(length);
    }
    for (int64_t c = 0; c < r.ncuts && complete; c++) {
      PendingCut cut = {"", {}, 0};
      int64_t patch = 0, groupbit = 0;
      complete = in.get(patch);
      for (double *v : {cut.crack.a, cut.crack.b, cut.crack.c})
        for (int d = 0; d < 3; d++) complete = complete && in.get(v[d]);
      complete = complete && in.get(groupbit);
      cut.crack.patch = (int) patch;
      cut.groupbit = (int) groupbit;
      cuts.push_back(cut);
    }
    // the per-atom fields of the per-atom records, by name (fix_pd_bonds_fields.cpp)
    complete = complete && read_field_list(in, file_fields) && in.at_end();
  }
  if (!complete)
    error->all(FLERR, "Fix pd/bonds: the restart file's bond record is damaged (inconsistent "
               "counts); it cannot be read");
  // every byte read, none past the record's end: now its checksum
  PDBondsRecord zeroed = r;
  zeroed.checksum = 0;
  const uint64_t sum = pd_record_checksum(buf + sizeof r, r.total_bytes - sizeof r,
                                          pd_record_checksum(&zeroed, sizeof zeroed));
  if (sum != (uint64_t) r.checksum)
    error->all(FLERR, "Fix pd/bonds: the restart file's bond record fails its checksum: the file is "
               "damaged (its bonds, damage or fracture totals would be misread); write it again or "
               "continue from another restart file");
  take_field_list(file_fields);
  // the pair style now differs from the one that wrote the file
  static const char *const other = "the file was written with another pd/ pair style, model or "
      "failure law: continue with the pair_style and pair_coeff that wrote it";
  if (r.weights != use_weights)
    error->all(FLERR, "Fix pd/bonds: restart file bonds {} weights, the pair style now {}; {}",
               r.weights ? "carry" : "carry no", use_weights ? "needs them" : "does not", other);
  if (r.history != nhistory)
    error->all(FLERR, "Fix pd/bonds: restart file bonds carry {} history values, the pair style "
               "now needs {}; {}", r.history, nhistory, other);

  built = (int) r.built;
  resize_tables((int) r.maxpartner);
  family_key = r.family_key;
  intact_at_map = (bigint) r.intact_at_map;
  // totals are kept once, on rank 0, so the global sums carry over
  nlost_local = comm->me == 0 ? (bigint) r.lost : 0;
  PDFractureRecord::Totals totals;
  totals.broken = (bigint) r.broken;
  totals.breaks_since_map = (bigint) r.breaks_since_map;
  totals.dissipated = r.dissipated;
  totals.dissipated_joule = r.dissipated_joule;
  totals.any_broken = (int) r.any_broken;
  totals.fresh_step = (bigint) r.fresh_step;
  record.restore(totals);
  record.restore_fresh(std::move(fresh_pairs), std::move(fresh_lengths));
  pending_cuts = std::move(cuts);
}
