/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: the global restart record of the bond store (fix
   pd/bonds), declared in one place.

   Layout: the fixed part, PDBondsRecord below (a tag, the version, its own
   size, then named fields, every one 8 bytes wide so that the struct has
   no padding), followed by variable-length lists in the order of their
   counts in the fixed part. write_restart fills the struct, restart()
   checks tag, version and sizes before it reads any field, and refuses
   an unknown version or a size mismatch with an ERROR that names the
   format it found and the one it expects; then the checksum of the whole
   record (pd_record_checksum, with the checksum field zero), so that a
   damaged byte anywhere in it is an ERROR, not a different run. Each
   atom's restart record ends with the checksum of its own values.

   Changing the record: add the field (8 bytes: int64_t or double) at the
   end of its group, bump PD_BONDS_RECORD_VERSION, fill the field in
   FixPDBonds::write_restart and read it in FixPDBonds::restart
   (fix_pd_bonds_restart.cpp). A new list: its count at the end of the
   counts, its entries after the last list (PDRecordWriter/Reader below).
   The header (tag, version, fixed_bytes, total_bytes) never moves: every
   version is recognized by it. The per-atom restart layout
   (FixPDBonds::pack_exchange) is covered by the same version: bump it
   when that changes too.
------------------------------------------------------------------------- */

#ifndef LMP_PD_BONDS_RECORD_H
#define LMP_PD_BONDS_RECORD_H

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace LAMMPS_NS {

// The version this build writes and reads.
constexpr int64_t PD_BONDS_RECORD_VERSION = 2;
// The record's first 8 bytes, where the records before versioning had
// their format tag as a double (20261201.1).
constexpr char PD_BONDS_RECORD_TAG[8] = {'P', 'D', 'B', 'O', 'N', 'D', 'S', '\0'};

struct PDBondsRecord {
  // -- header: checked before anything else is read --
  char tag[8];
  int64_t version;            // PD_BONDS_RECORD_VERSION of the writer
  int64_t fixed_bytes;        // sizeof(PDBondsRecord) of the writer
  int64_t total_bytes;        // the whole record: this struct and the lists after it

  // -- the families --
  int64_t built;              // 1: the families exist
  int64_t maxpartner;         // row length of the per-atom bond tables
  int64_t weights;            // 1: bonds carry a quadrature weight
  int64_t history;            // history values per bond
  double family_key;          // fingerprint of the settings they were built for (PDFamilySpec::key)
  int64_t lost;               // intact bonds lost so far, all ranks
  int64_t intact_at_map;      // intact bonds at the last mapping (-1: none yet)

  // -- the fracture record (PDFractureRecord::Totals) --
  int64_t broken;             // bonds broken by fracture, all ranks
  int64_t breaks_since_map;   // bonds broken or cut since the last mapping
  double dissipated;          // dissipated energy, sum of energy densities
  double dissipated_joule;    // the same in energy units
  int64_t any_broken;         // some bond is broken (fracture or pre-crack)
  int64_t fresh_step;         // step of the last evaluation that broke bonds

  // -- counts of the lists that follow the struct, in this order --
  int64_t nfresh;             // fresh bonds: owner tag, partner tag (int64), length (double)
  int64_t ncuts;              // pending cuts: patch (int64), a, b, c (9 doubles), groupbit (int64)
  // then the per-atom field list, which carries its own count (int64), then
  // per field width, flags (int64) and name (put_string). A new list: its
  // count here, its entries after the cuts.

  // -- integrity --
  int64_t checksum;           // pd_record_checksum of all total_bytes, this field zero
};

// FNV-1a, 64 bits: every byte changes the sum, and one flipped bit or byte
// never leaves it unchanged.
inline uint64_t pd_record_checksum(const void *bytes, size_t n, uint64_t sum = 14695981039346656037ULL)
{
  const unsigned char *p = static_cast<const unsigned char *>(bytes);
  for (size_t k = 0; k < n; k++) sum = (sum ^ p[k]) * 1099511628211ULL;
  return sum;
}

// An atom's restart values summed as one double: the checksum's top 52
// bits, an integer a double holds exactly, whatever copies it.
inline double pd_record_checksum_value(const double *values, int n)
{
  return (double) (pd_record_checksum(values, sizeof(double) * (size_t) n) >> 12);
}

static_assert(std::is_trivially_copyable<PDBondsRecord>::value, "the record is written as bytes");
static_assert(sizeof(PDBondsRecord) % 8 == 0, "every field of the record is 8 bytes wide");

// The record as bytes, written in order.
class PDRecordWriter {
 public:
  template <typename T> void put(const T &v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    const char *p = reinterpret_cast<const char *>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  void put_string(const std::string &s)
  {
    put((int64_t) s.size());
    bytes.insert(bytes.end(), s.begin(), s.end());
  }
  std::vector<char> bytes;
};

// The record's bytes read in order, never past its end: get() returns
// false (and leaves v) when the value would reach beyond it.
class PDRecordReader {
 public:
  PDRecordReader(const char *buf, size_t size) : buf(buf), size(size), pos(0) {}
  template <typename T> bool get(T &v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    if (size - pos < sizeof(T)) return false;
    memcpy(&v, buf + pos, sizeof(T));
    pos += sizeof(T);
    return true;
  }
  bool get_string(std::string &s)
  {
    int64_t n;
    if (!get(n) || n < 0 || (uint64_t) n > size - pos) return false;
    s.assign(buf + pos, (size_t) n);
    pos += (size_t) n;
    return true;
  }
  bool at_end() const { return pos == size; }

 private:
  const char *buf;
  size_t size, pos;
};

}    // namespace LAMMPS_NS

#endif
