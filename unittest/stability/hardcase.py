"""The checks every hard case of the stability suite makes, and
how it runs: reduced in make test, full (PDEXT_VALIDATE=1) in make validate.

A scene is an input deck that defines v_etot (kinetic + elastic +
dissipated energy in joules: include ENERGY) and v_work (the work put in so far, joules; 0 when nothing drives
the scene), prints them with 'thermo_style custom step dt time v_etot
v_work atoms', and dumps 'id x y z' every few steps into the file named by
the variable 'frames'. assess() then asserts:
  - the run finishes: no ERROR, 'Loop time' printed;
  - no NaN or inf in the thermo output;
  - no lost atoms;
  - energy never grows beyond the work put in: etot - work <= etot(0) +
    tol (etot(0) + max work), tol stated by the scene (time integration
    error; a blow-up multiplies the energy);
  - no interpenetration: particles that were not bond partners (farther
    apart than the horizon at the start) stay more than 'apart' spacings
    apart in every frame."""
import math
import os
import re
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../lammps"))
from lmptest import *  # noqa: E402,F401

FULL = os.environ.get("PDEXT_VALIDATE") == "1"
HERE = os.path.dirname(os.path.abspath(__file__))
POTENTIALS = os.path.abspath(os.path.join(HERE, "../../potentials"))

# kinetic + elastic + dissipated (broken bonds) energy in joules
ENERGY = replace_exact(ENERGY_JOULES, "variable etot equal c_KEJ+c_PEJ\n",
                       "compute frac all pd/fracture\nvariable etot equal c_KEJ+c_PEJ+c_frac[2]\n")
THERMO = "thermo_style custom step dt time v_etot v_work atoms\nthermo_modify lost warn norm no\n"
ADAPTIVE = "fix ts all pd/timestep"


def scene_dir(thermo=THERMO):
    """A work directory holding the ENERGY and thermo blocks as energy.in
    and thermo.in (the decks include them)."""
    d = workdir()
    open(f"{d}/energy.in", "w").write(ENERGY)
    open(f"{d}/thermo.in", "w").write(thermo)
    return d


def summary(out, tag):
    """The line a deck prints starting with tag (its own numbers), or ''."""
    return next((l for l in out.splitlines() if l.startswith(tag)), "")


def check_reached(scene, r, tmax):
    """The adaptive run got to the simulated time (the last thermo row is
    the halt's step: the decks halt on thermo steps)."""
    check(f"{scene}: the adaptive run reaches the simulated time", r.get("time", 0) >= tmax * 0.999,
          f"{r.get('time', 0):.3g} s of {tmax:.3g}")


def read_frames(path):
    """[(step, {id: (x, y, z)})] of a text dump with 'id x y z'."""
    frames, lines = [], open(path).read().split("ITEM: TIMESTEP\n")[1:]
    for block in lines:
        rows = block.splitlines()
        step = int(rows[0])
        start = next(i for i, r in enumerate(rows) if r.startswith("ITEM: ATOMS"))
        pos = {}
        for r in rows[start + 1:]:
            w = r.split()
            if len(w) == 4:
                pos[int(w[0])] = (float(w[1]), float(w[2]), float(w[3]))
        frames.append((step, pos))
    return frames


def nearest_stranger(frames, horizon, spacing):
    """The smallest distance, in spacings, between two particles that were
    farther apart than the horizon in the first frame (never bond
    partners), over all frames; only distances below one spacing are
    searched (1.0 means none came closer)."""
    ref = frames[0][1]
    h2 = (horizon * (1 + 1e-9)) ** 2
    best = 1.0
    for _, pos in frames[1:]:
        cells = {}
        for i, p in pos.items():
            cells.setdefault(tuple(int(math.floor(c / spacing)) for c in p), []).append(i)
        for key, members in cells.items():
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for dz in (-1, 0, 1):
                        other = cells.get((key[0] + dx, key[1] + dy, key[2] + dz))
                        if not other:
                            continue
                        for i in members:
                            pi = pos[i]
                            for j in other:
                                if j <= i:
                                    continue
                                pj = pos[j]
                                d2 = (pi[0] - pj[0]) ** 2 + (pi[1] - pj[1]) ** 2 + (pi[2] - pj[2]) ** 2
                                if d2 >= (best * spacing) ** 2:
                                    continue
                                ri, rj = ref.get(i), ref.get(j)
                                if ri and rj and sum((a - b) ** 2 for a, b in zip(ri, rj)) > h2:
                                    best = math.sqrt(d2) / spacing
    return best


def run_scene(deck, d, variables, name):
    """Runs the deck; returns (output, thermo rows, frames, wall seconds)."""
    variables = dict(variables, frames=f"{name}.frames", potentials=POTENTIALS)
    start = time.time()
    out, rows = run(deck, d, variables=variables, name=f"in.{name}", expect_error=True)
    wall = time.time() - start
    path = os.path.join(d, f"{name}.frames")
    frames = read_frames(path) if os.path.exists(path) else []
    return out, rows, frames, wall


def outcome(out, rows, frames, horizon, spacing, tol, apart):
    """What happened, as a dict: each criterion's value and whether it held."""
    r = {"out": out, "error": next((l for l in out.splitlines() if l.startswith("ERROR")), None),
         "finished": "Loop time" in out and "ERROR" not in out}
    vals = [v for row in rows for v in row.values()]
    r["finite"] = bool(rows) and all(math.isfinite(v) for v in vals)
    r["atoms"] = bool(rows) and all(row["Atoms"] == rows[0]["Atoms"] for row in rows)
    if rows:
        e0 = rows[0]["v_etot"]
        wmax = max(abs(row["v_work"]) for row in rows)
        r["growth"] = max((row["v_etot"] - row["v_work"] - e0) / (e0 + wmax) for row in rows)
        r["steps"] = int(rows[-1]["Step"])
        r["time"] = rows[-1]["Time"]
        r["dtmin"] = min(row["Dt"] for row in rows)
    else:
        r["growth"] = math.inf
    r["energy"] = r["growth"] <= tol
    r["nearest"] = nearest_stranger(frames, horizon, spacing) if len(frames) > 1 else 0.0
    r["apart"] = r["nearest"] > apart
    r["stable"] = all(r[k] for k in ("finished", "finite", "atoms", "energy", "apart"))
    return r


def describe(r):
    if r.get("error"):
        return r["error"][:140]
    return (f"{r.get('steps', 0)} steps, {r.get('time', 0):.3g} s simulated, smallest dt {r.get('dtmin', 0):.3g}; "
            f"energy growth {r['growth']:+.3g}; nearest non-partner {r['nearest']:.3f} spacings")


def setup_estimates(out):
    """The setup's stable steps: the material's (MS07 eq. 43), the contact springs' (inf: no contact)."""
    est = log_value(out, r"stable time step estimate \(MS07 eq. 43\) ([0-9.eE+-]+)")
    contact = log_value(out, r"stable time step estimate of the contact springs ([0-9.eE+-]+)")
    return est, contact if math.isfinite(contact) else math.inf


def fixed_runs(deck, d, base, scene, horizon, spacing, tol, apart, out):
    """The scene at the fixed steps a user would take from the setup report
    of 'out': 0.8 of the material's estimate, and 0.8 of the contact
    springs' where that is smaller. Prints each; returns {label: outcome}."""
    est, est_contact = setup_estimates(out)
    print(f"{scene}: setup estimates: material (MS07 eq. 43) {est:.3g}, contact springs {est_contact:.3g}")
    results = {}
    steps = [(0.8 * est, "0.8 of the setup estimate")]
    if est_contact < est:
        steps.append((0.8 * est_contact, "0.8 of the contact springs' estimate"))
    for dt, what in steps:
        fout, frows, fframes, fwall = run_scene(deck, d, dict(base, adapt="", dt=dt), f"fixed{dt:.3g}")
        fixed = outcome(fout, frows, fframes, horizon, spacing, tol, apart)
        print(f"SCENE {scene}: fixed dt {dt:.3g} ({what}): {'stable' if fixed['stable'] else 'UNSTABLE'}: "
              f"{describe(fixed)}; {fwall:.1f} s wall")
        results[what] = fixed
    return results


def assess(scene, r, tol, apart, wall):
    """The suite's assertions on one adaptive run."""
    what = f"{scene}: "
    check(what + "the run finishes", r["finished"], r.get("error") or "")
    check(what + "no NaN or inf", r["finite"])
    check(what + "no lost atoms", r["atoms"])
    check_le(what + "energy growth beyond the work put in (relative)", r["growth"], tol,
             "time integration error; a blow-up multiplies the energy")
    check(what + f"particles that were never bond partners stay more than {apart} spacings apart",
          r["apart"], f"nearest {r['nearest']:.3f} spacings")
    print(f"SCENE {scene}: adaptive: {describe(r)}; {wall:.1f} s wall")
