"""Drive build/lmp from Python for the LAMMPS-level tests.

Every check prints PASS/FAIL with its tolerance; finish() prints the
'N passed, N failed' line and sets the exit status."""
import math
import os
import re
import subprocess
import sys
import tempfile

LMP = os.environ.get("PDEXT_LMP") or os.path.join(os.path.dirname(__file__), "../../build/lmp")
LMP = os.path.abspath(LMP)
_counts = {"pass": 0, "fail": 0}
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")


def workdir():
    return tempfile.mkdtemp(prefix="pdtest-")


# The neighbor settings a test deck runs with when it states none: LAMMPS's
# default delay changed (10 before 2026, 0 since), so every tree is told.
NEIGHBOR_DEFAULTS = "neigh_modify every 1 delay 10 check yes\n"


def with_neighbor_defaults(script):
    """The script, led by NEIGHBOR_DEFAULTS unless it sets neigh_modify itself."""
    if re.search(r"^\s*neigh_modify\s", script, re.M):
        return script
    return NEIGHBOR_DEFAULTS + script


def run(script, cwd, ranks=1, expect_error=False, variables=None, name="in.test", as_is=False):
    """Run an input script; returns (stdout+stderr, thermo rows of the last run).
    as_is: exactly as given (a deck users copy runs with their LAMMPS's
    defaults), else led by NEIGHBOR_DEFAULTS."""
    path = os.path.join(cwd, name)
    with open(path, "w") as f:
        f.write(script if as_is else with_neighbor_defaults(script))
    cmd = [LMP, "-in", name, "-echo", "none", "-log", name + ".log"]
    for k, v in (variables or {}).items():
        cmd += ["-var", k, str(v)]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, env=MPI_ENV, timeout=900)
    out = p.stdout + p.stderr
    if p.returncode != 0 and not expect_error:
        print(out[-3000:])
        raise RuntimeError(f"lmp failed ({p.returncode}) in {cwd}")
    return out, thermo(out)


def thermo(out):
    """Rows (dicts) of every thermo block in the output, last block last."""
    rows, header = [], None
    for line in out.splitlines():
        w = line.split()
        if w and w[0] == "Step":
            header, rows = w, []
        elif header and len(w) == len(header):
            try:
                rows.append(dict(zip(header, map(float, w))))
            except ValueError:
                header = None
        elif w[:2] == ["Loop", "time"]:
            header = None
    return rows


def read_dump(path):
    """{id: [values...]} from a text dump with one ITEM: ATOMS block."""
    lines = open(path).read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    return {int(l.split()[0]): [float(v) for v in l.split()[1:]] for l in lines[start + 1:] if l.strip()}


def max_rel_diff(a, b):
    """Largest difference between two dumps, relative to their largest value."""
    if set(a) != set(b):
        return math.inf
    diff = max(abs(x - y) for k in a for x, y in zip(a[k], b[k]))
    scale = max(abs(x) for k in a for x in a[k])
    return diff / scale


def check(what, ok, detail=""):
    print(("PASS " if ok else "FAIL ") + what + (f"  ({detail})" if detail else ""))
    _counts["pass" if ok else "fail"] += 1


def check_le(what, value, limit, reason=""):
    check(what, value <= limit, f"{value:.3g} <= {limit:.3g}" + (f"; {reason}" if reason else ""))


def log_value(out, pattern):
    m = re.search(pattern, out)
    return float(m.group(1)) if m else math.nan


def stated_value(text):
    """A number as a README states it ("102,650", "-0.292", "9.80e-05")."""
    return float(text.replace(",", ""))


def agrees(printed, stated):
    """Whether a printed number (a float) is the one a README states
    (its digits): within 1% of it, and at least half a unit of its last
    digit. The README's digits are one run's; fracture counts and crack
    paths follow round-off, which another compiler or vector width
    changes, and 1% leaves room for that."""
    s = stated_value(stated)
    mantissa, _, exponent = stated.replace(",", "").lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    half_unit = 0.5 * 10.0 ** (int(exponent or 0) - decimals)
    return abs(printed - s) <= max(0.01 * abs(s), half_unit)


def fnv1a(data, h=14695981039346656037):
    """64-bit FNV-1a, the checksum of the bond store's restart records."""
    for b in data:
        h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h


def reseal_bond_record(raw):
    """A restart file whose bond store global record was edited, with its
    checksum made right again: what another build that wrote those bytes
    would have written (the checksum is the record's last fixed field)."""
    import struct
    at = raw.index(b"PDBONDS\0")
    fixed, total = struct.unpack_from("<qq", raw, at + 16)
    out = bytearray(raw)
    out[at + fixed - 8:at + fixed] = bytes(8)
    out[at + fixed - 8:at + fixed] = struct.pack("<Q", fnv1a(out[at:at + total]))
    return bytes(out)


def replace_exact(text, old, new, count=1):
    """text with `old` replaced by `new`, which must occur exactly `count`
    times: an edit of an input deck that no longer matches would otherwise
    leave the deck unchanged and the test testing something else."""
    found = text.count(old)
    if found != count:
        raise ValueError(f"replace_exact: expected {count} occurrence(s) of {old!r}, found {found}")
    return text.replace(old, new)


def sub_exact(pattern, new, text, count=1, flags=0):
    """re.sub that must replace exactly `count` matches (see replace_exact)."""
    result, found = re.subn(pattern, new, text, flags=flags)
    if found != count:
        raise ValueError(f"sub_exact: expected {count} match(es) of /{pattern}/, found {found}")
    return result


def finish():
    print(f"{_counts['pass']} passed, {_counts['fail']} failed")
    sys.exit(1 if _counts["fail"] else 0)


# The benchmark and parity block: simple cubic, spacing 5e-4,
# horizon 3 spacings, K = 14.9 GPa, density 2200, volume 1.25e-10.
SPACING, HORIZON, BULK, DENSITY, VOLUME = 0.0005, 0.0015001, 14.9e9, 2200.0, 1.25e-10
MICROMODULUS = 18 * BULK / (math.pi * HORIZON ** 4)
SHEAR = 0.6 * BULK   # nu = 1/4


def block(n, boundary="p p p"):
    return f"""units si
boundary {boundary}
atom_style peri
atom_modify map array
lattice sc {SPACING}
region box block 0 {n} 0 {n} 0 {n}
create_box 1 box
create_atoms 1 box
set group all density {DENSITY}
set group all volume {VOLUME}
"""


def two_blocks(b0=10):
    """Two simple cubic blocks 5 spacings long in x (types and groups a
    and b), b from x = b0 spacings on, periodic in y and z, shrink-wrapped
    in x: the colliding bodies of the contact tests."""
    return f"""units si
boundary s p p
atom_style peri
atom_modify map array
lattice sc {SPACING}
region box block -1 17 0 8 0 8
create_box 2 box
region a block 0 5 INF INF INF INF
region b block {b0} {b0 + 5} INF INF INF INF
create_atoms 1 region a
create_atoms 2 region b
group a type 1
group b type 2
"""


def plate(n, boundary="p p p"):
    """A 2D square-lattice plate, 1 mm thick (volume = spacing^2 x thickness)."""
    return f"""units si
dimension 2
boundary {boundary}
atom_style peri
atom_modify map array
lattice sq {SPACING}
region box block 0 {n} 0 {n} -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density {DENSITY}
set group all volume {SPACING * SPACING * 1e-3}
"""


# A rough velocity field (amplitude 0.5 m/s, strains ~1e-4), the same for
# any rank count because it depends on atom IDs only.
ROUGH_VELOCITY = """variable vx atom 0.5*sin(12.9898*id)
variable vy atom 0.5*sin(78.233*id)
variable vz atom 0.5*sin(37.719*id)
velocity all set v_vx v_vy v_vz units box
"""

PAIRS = {
    "peri/pmb": f"pair_style peri/pmb\npair_coeff * * {MICROMODULUS!r} {HORIZON} 1.0 0.0\n",
    "pd/bond legacy": f"pair_style pd/bond legacy\npair_coeff * * pmb c {MICROMODULUS!r} horizon {HORIZON}\n",
    "pd/bond": f"pair_style pd/bond\npair_coeff * * pmb K {BULK} horizon {HORIZON}\n",
    "peri/lps": f"pair_style peri/lps\npair_coeff * * {BULK} {SHEAR} {HORIZON} 1.0 0.0\n",
    "pd/ordinary legacy": f"pair_style pd/ordinary legacy\npair_coeff * * K {BULK} G {SHEAR} horizon {HORIZON} m 0.5\n",
    "pd/ordinary": f"pair_style pd/ordinary\npair_coeff * * K {BULK} G {SHEAR} horizon {HORIZON} m 0.5\n",
}

PAIRS["pd/ordinary 2D m=0"] = ("pair_style pd/ordinary plane stress thickness 1e-3\n"
                               f"pair_coeff * * E 3.5e9 nu 0.35 horizon {HORIZON} m 0\n")

# kinetic and elastic energy in joules (the thermo energies are sums of
# energy densities): v_etot = c_KEJ + c_PEJ
ENERGY_JOULES = """compute vf all property/atom vfrac
compute keV all ke/atom
variable keJ atom c_keV*c_vf
compute KEJ all reduce sum v_keJ
compute peV all pe/atom
variable peJ atom c_peV*c_vf
compute PEJ all reduce sum v_peJ
variable etot equal c_KEJ+c_PEJ
"""

DUMP = "write_dump all custom {file} id x y z modify sort id format float %.17g\n"
