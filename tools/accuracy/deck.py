"""Input-deck pieces shared by the accuracy quantities: the material (from
potentials/materials.pd), the lattices, the pair lines of each style, and
running LAMMPS (one rank) with its Loop time.

Lengths: every lattice is described by its equivalent spacing h = V^(1/d)
(V the particle volume per unit thickness in 2D), and the horizon is
ratio x h, the measure the pair styles check (horizon > 1.01 spacings)."""
import math
import os
import re
import shutil
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
MATERIALS = os.path.join(ROOT, "potentials", "materials.pd")
THICK = 1.0e-3            # 2D plate thickness (m)
# Every deck states its neighbor settings: LAMMPS's defaults differ
# between versions (the reneighboring delay) and units si's default skin
# (1 mm) is several spacings here. The skin is a fraction of the spacing.
SKIN = 0.2
NEIGHBOR = "neighbor {skin} bin\nneigh_modify every 1 delay 0 check yes\n"
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def material(name="PMMA"):
    """{key: value} of one material of potentials/materials.pd."""
    values, inside = {}, False
    for raw in open(MATERIALS):
        w = raw.split("#")[0].split()
        if not w:
            continue
        if w[0] == "material":
            inside = w[1] == name
        elif w[0] == "end":
            if inside:
                return values
        elif inside:
            values[w[0]] = float(w[1])
    raise KeyError(f"material {name} not in {MATERIALS}")


# ----------------------------------------------------------------------
# Lattices. dims, the LAMMPS lattice name, its constant a for a given
# equivalent spacing h, and the cell of the periodic box in units of a.

LATTICES = {
    # name: (dims, LAMMPS style, a / h, cell lengths in a)
    "sc": (3, "sc", 1.0, (1.0, 1.0, 1.0)),
    "fcc": (3, "fcc", 4.0 ** (1.0 / 3.0), (1.0, 1.0, 1.0)),       # 4 atoms per a^3
    "square": (2, "sq", 1.0, (1.0, 1.0, 1.0)),
    "hex": (2, "hex", math.sqrt(2.0 / math.sqrt(3.0)), (1.0, math.sqrt(3.0), 1.0)),   # 2 atoms per a x a sqrt(3)
}


def base_lattice(lattice):
    """'sc-jitter' -> 'sc': a jittered lattice is its base lattice with
    every particle moved at random (before the bonds are built)."""
    return lattice.replace("-jitter", "")


def dims_of(lattice):
    return LATTICES[base_lattice(lattice)][0]


def volume(lattice, h):
    return h ** 3 if dims_of(lattice) == 3 else h * h * THICK


def header(lattice, h, boundary, orient=""):
    """units, dimension, atom style and the lattice command (with its
    orient keywords, if any)."""
    dims, style, a_over_h, _ = LATTICES[base_lattice(lattice)]
    return ("units si\n" + ("dimension 2\n" if dims == 2 else "") +
            f"boundary {boundary}\natom_style peri\natom_modify map array\n" + NEIGHBOR.format(skin=repr(SKIN * h)) +
            # room for the families' neighbor lists: 6 spacings with
            # partial-volume quadrature (cutoff past the horizon)
            # overflow LAMMPS's default of 2000
            "neigh_modify one 8000 page 80000\n"
            f"lattice {style} {a_over_h * h!r}{orient}\n")


def jitter(lattice, h, boundary, seed=4711, amplitude=0.2):
    """For a '-jitter' lattice: random displacements (uniform, +-amplitude
    spacings per component), made the reference configuration by a
    write_data / read_data round trip (atom_style peri's reference
    positions x0 are those of create_atoms or read_data; displace_atoms
    alone would strain the lattice). Empty otherwise. Regions defined
    before it are gone after it."""
    if not lattice.endswith("-jitter"):
        return ""
    a = amplitude * h
    z = "0.0" if dims_of(lattice) == 2 else repr(a)
    return (f"displace_atoms all random {a!r} {a!r} {z} {seed} units box\n"
            "write_data jitter.data\nclear\n" + header(lattice, h, boundary) + "read_data jitter.data\n")


def random_volumes(lattice, h, seed, spread):
    """Every particle's volume drawn uniformly within +-spread of the
    lattice's (after 'set ... volume'); empty for spread 0."""
    if not spread:
        return ""
    v = volume(lattice, h)
    return (f"variable vrand atom {v!r}*(1+{spread!r}*(2*random(0,1,{seed})-1))\n"
            "set group all volume v_vrand\n")


def periodic_block(lattice, h, min_length):
    """A triclinic-capable periodic block of whole lattice cells, each side
    at least min_length long. Returns (text, natoms, box lengths)."""
    dims, _, a_over_h, cell = LATTICES[base_lattice(lattice)]
    a = a_over_h * h
    n = [max(2, math.ceil(min_length / (cell[i] * a)) + 1) for i in range(3)]
    lengths = [n[i] * cell[i] * a for i in range(dims)]
    zrange = f"{-0.5 * a!r} {0.5 * a!r}" if dims == 2 else f"0 {lengths[2]!r}"
    text = header(lattice, h, "p p p")
    text += (f"region box prism 0 {lengths[0]!r} 0 {lengths[1]!r} {zrange} 0 0 0 units box\n"
             "create_box 1 box\ncreate_atoms 1 box\n")
    text += jitter(lattice, h, "p p p")
    text += f"set group all density {material()['density']}\nset group all volume {volume(lattice, h)!r}\n"
    per_cell = {"sc": 1, "fcc": 4, "square": 1, "hex": 2}[base_lattice(lattice)]
    natoms = per_cell * n[0] * n[1] * (n[2] if dims == 3 else 1)
    return text, natoms, lengths


# ----------------------------------------------------------------------
# Pair lines. A 'setting' is a dict with at least style, ratio and
# lattice, and optionally influence, m, quadrature, law, strain.

def model(setting):
    """'3d', 'plane stress' or 'plane strain'."""
    if dims_of(setting["lattice"]) == 3:
        return "3d"
    return setting.get("plane", "plane stress")


# the styles with directional_correction (named in every deck, 'directional':
# False in a setting for 'no')
DIRECTIONAL_STYLES = ("pd/bond", "pd/ordinary")


def profile_words(setting):
    """' profile <name>' where a case names the energy law's profile, else ''."""
    return f" profile {setting['profile']}" if setting.get("profile") else ""


def fail_words(setting, gc):
    """The 'fail ...' words of a case with a failure law ('law', and for
    the energy law an optional 'profile'), G_c given as gc."""
    return f"fail {setting['law']} Gc {gc}" + profile_words(setting)


def pair_lines(setting, h, fail="", mat="PMMA"):
    """pair_style and pair_coeff lines; fail = '' or e.g. 'fail energy Gc 400'."""
    p = material(mat)
    style, delta = setting["style"], setting["ratio"] * h * (1 + 1e-6)
    words = [f"pair_style {style}"]
    if style == "pd/corr":
        words.append(f"model elastic strain {setting.get('strain', 'extended')}")
    if setting.get("influence") and style != "pd/bond":
        words.append(f"influence {setting['influence']}")
    # always named: the styles' defaults may differ (pd/bond: partial)
    words.append(f"quadrature {setting.get('quadrature', 'point')}")
    if style in DIRECTIONAL_STYLES:
        words.append(f"directional_correction {'no' if setting.get('directional') is False else 'yes'}")
    if "recontact" in setting:
        words.append(f"recontact {setting['recontact']}")
    if model(setting) != "3d":
        words.append(f"{model(setting)} thickness {THICK!r}")
    line = " ".join(words) + "\n"
    if style == "pd/bond":
        line += f"pair_coeff * * pmb E {p['E']!r} horizon {delta!r} {fail}\n"
    else:
        m = f" m {setting['m']}" if "m" in setting else ""
        line += f"pair_coeff * * E {p['E']!r} nu {p['nu']!r} horizon {delta!r}{m} {fail}\n"
    return line


def poisson(setting, mat="PMMA"):
    """Poisson's ratio of the material the pair lines define: bond-based
    materials have a fixed one (1/4 in 3D and plane strain, 1/3 in plane
    stress)."""
    if setting["style"] == "pd/bond":
        return 1.0 / 3.0 if model(setting) == "plane stress" else 0.25
    return material(mat)["nu"]


def classical_lame(setting, mat="PMMA"):
    """(lambda, mu) of the classical in-plane (2D) or 3D law."""
    E, nu = material(mat)["E"], poisson(setting, mat)
    mu = E / (2 * (1 + nu))
    if model(setting) == "plane stress":
        return E * nu / (1 - nu * nu), mu
    return E * nu / ((1 + nu) * (1 - 2 * nu)), mu


# ----------------------------------------------------------------------
# Running LAMMPS.

class LammpsError(RuntimeError):
    pass


def run(lmp, script, workdir, name="in.acc", variables=None, timeout=3600):
    """Run a deck on one rank; returns (output, seconds): the summed Loop
    times of its runs, and the wall time of the whole process."""
    path = os.path.join(workdir, name)
    with open(path, "w") as f:
        f.write(script)
    # line-buffered: an ERROR followed by MPI_Abort reaches the pipe
    cmd = (["stdbuf", "-oL", "-eL"] if shutil.which("stdbuf") else []) + \
        [lmp, "-in", name, "-echo", "none", "-log", name + ".log"]
    for k, v in (variables or {}).items():
        cmd += ["-var", k, str(v)]
    t0 = time.time()
    p = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, env=ENV, timeout=timeout)
    wall = time.time() - t0
    out = p.stdout + p.stderr
    if p.returncode != 0:
        err = [l for l in out.splitlines() if "ERROR" in l]
        raise LammpsError(f"{name}: lmp exit {p.returncode}: " + (err[0] if err else out[-500:]))
    return out, {"loop": loop_times(out), "wall": wall}


def loop_times(out):
    """The Loop time of each run, in order."""
    return [float(m.group(1)) for m in re.finditer(r"^Loop time of ([0-9.eE+-]+) on", out, re.M)]


def printed(out, tag):
    """Rows of the lines 'tag v1 v2 ...' written by print."""
    return [l.split()[1:] for l in out.splitlines() if l.split()[:1] == [tag]]


def accepts(lmp, workdir, pair_text, lattice="sc", h=1e-3):
    """True if a tiny deck with these pair lines runs 0 steps without error."""
    text, _, _ = periodic_block(lattice, h, 8 * h)
    try:
        run(lmp, text + pair_text + "run 0\n", workdir, name="in.probe", timeout=120)
        return True
    except (LammpsError, subprocess.TimeoutExpired):
        return False


# ----------------------------------------------------------------------
# The lines a user pastes into a deck for a measured setting: a is the
# spacing (V^(1/d)), the horizon a number of spacings, the material's
# constants as variables (${E}, ${nu}, ${Gc}, ${t} the plate thickness).

LATTICE_LINE = {"sc": "lattice sc ${a}", "square": "lattice sq ${a}", "sq": "lattice sq ${a}",
                "fcc": f"lattice fcc $({LATTICES['fcc'][2]:.6g}*a)",
                "hex": f"lattice hex $({LATTICES['hex'][2]:.6g}*a)"}


def user_lines(s):
    """The deck lines of a setting dict (the keys of the accuracy cases:
    style, lattice, plane, influence, strain, quadrature, directional, recontact,
    ratio, m or order, law, profile, spacing or h, dt_fraction; timestep, note:
    a comment line)."""
    lines = []
    a = s.get("spacing", s.get("h"))
    if a:
        lines.append(f"variable a equal {a:g}")
    lat = s.get("lattice")
    if lat:
        base = base_lattice({"sq": "square"}.get(lat, lat))
        lines.append(LATTICE_LINE[base] + ("  # particles moved at random by up to 0.2 a" if "jitter" in lat else ""))
    style = s.get("style", "")
    words = [f"pair_style {style}"]
    if style == "pd/corr":
        words.append(f"model elastic strain {s.get('strain', 'extended')}")
    if s.get("influence") and style != "pd/bond":
        words.append(f"influence {s['influence']}")
    words.append(f"quadrature {s.get('quadrature') or 'point'}")
    if style in DIRECTIONAL_STYLES:
        words.append(f"directional_correction {'no' if s.get('directional') is False else 'yes'}")
    if s.get("recontact"):
        words.append(f"recontact {s['recontact']}")
    dims = dims_of({"sq": "square"}.get(lat, lat)) if lat else s.get("dim", 3)
    if dims == 2:
        words.append(f"{s.get('plane', 'plane stress')} thickness ${{t}}")
    lines.append(" ".join(words))
    coeff = "pair_coeff * * pmb E ${E}" if style == "pd/bond" else "pair_coeff * * E ${E} nu ${nu}"
    coeff += f" horizon $({float(s['ratio'])!r}*a)"
    m = s.get("m", s.get("order"))
    if m is not None and style != "pd/bond":
        coeff += f" m {m:g}"
    if s.get("law"):
        coeff += " " + fail_words(s, "${Gc}")
    lines.append(coeff)
    if s.get("dt_fraction") is not None:
        lines.append(f"fix dt all pd/timestep safety {s['dt_fraction']:g}")
    if s.get("timestep"):
        lines.append(f"timestep {s['timestep']:g}")
    if s.get("note"):
        lines.append("# " + s["note"])
    return lines
