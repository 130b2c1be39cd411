#!/usr/bin/env python3
"""make bench: time the pd/ styles against LAMMPS's PERI styles and print
the tables described in bench/README.md.

    report.py --lmp build/lmp [--full] [--passes 3] [--clock cpu|wall] [--logs DIR]

Default: the benchmark block (16^3, 200 steps, 1 rank), every style in
turn in one LAMMPS process, the whole list run three times (interleaved),
the smallest time of the passes kept per style. --full adds the size sweep
(each size and style its own process), the family build, peak memory per
bond and the 2-rank efficiency. Python standard library only.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")

# ---------------------------------------------------------------- settings

BLOCK_STEPS = 200
# Every style of the block, in the order of one pass (bench/pairs/<style>.in)
# (each effect next to its baseline, so that the two see about the same load)
BLOCK_STYLES = [
    "peri_pmb", "pd_bond", "pd_bond_fail_stretch", "pd_bond_contact", "pd_bond_thermo", "pd_bond_peratom", "pd_bond_stress", "pd_bond_timestep", "pd_bond_fragments", "pd_bond_no_directional", "pd_bond_microplastic",
    "pd_bond_legacy", "pd_bond_legacy_fail", "pd_bond_legacy_fail_alpha",
    "peri_lps", "pd_ordinary", "pd_ordinary_fail_stretch", "pd_ordinary_fail_energy",
    "pd_ordinary_contact", "pd_ordinary_thermo", "pd_ordinary_peratom", "pd_ordinary_stress", "pd_ordinary_timestep", "pd_ordinary_no_directional", "pd_ordinary_m0", "pd_ordinary_m-1", "pd_ordinary_legacy",
    "pd_corr_classical", "pd_corr_j2", "pd_corr_jc", "pd_corr_extended",
]
# The legacy styles have no bond count of their own in the log (PERI prints
# each bond twice): they use the families of this style, the same ones
LEGACY_BONDS_FROM = "pd_bond"

# (new, legacy, goal): speed-up = legacy time / new time
SPEEDUPS = [
    ("pd_bond", "peri_pmb", 18.0),
    ("pd_bond_legacy", "peri_pmb", None),
    ("pd_ordinary", "peri_lps", 20.0),
    ("pd_ordinary_legacy", "peri_lps", None),
]

# (effect, style, baseline, bar): cost = time of style / time of baseline
EFFECTS = [
    ("nonlinear strain", "pd_ordinary_m0", "pd_ordinary", 1.3),
    ("nonlinear strain", "pd_ordinary_m-1", "pd_ordinary", 1.5),
    ("failure", "pd_bond_fail_stretch", "pd_bond", 1.2),
    ("failure", "pd_bond_legacy_fail", "pd_bond_legacy", 1.2),
    ("failure", "pd_bond_legacy_fail_alpha", "pd_bond_legacy", 1.2),
    ("failure", "pd_ordinary_fail_stretch", "pd_ordinary", 1.2),
    ("failure", "pd_ordinary_fail_energy", "pd_ordinary", 1.2),
    ("contact", "pd_bond_contact", "pd_bond", 1.05),
    ("contact", "pd_ordinary_contact", "pd_ordinary", 1.05),
    ("energy and virial", "pd_bond_thermo", "pd_bond", 1.1),
    ("energy and virial", "pd_ordinary_thermo", "pd_ordinary", 1.1),
    ("per-atom energy", "pd_bond_peratom", "pd_bond", 1.1),
    ("per-atom energy", "pd_ordinary_peratom", "pd_ordinary", 1.1),
    ("per-atom virial", "pd_bond_stress", "pd_bond", 1.1),
    ("per-atom virial", "pd_ordinary_stress", "pd_ordinary", 1.1),
    ("adaptive step", "pd_bond_timestep", "pd_bond", 1.1),
    ("adaptive step", "pd_ordinary_timestep", "pd_ordinary", 1.1),
    ("fragments", "pd_bond_fragments", "pd_bond", 1.02),
    ("directional correction", "pd_bond", "pd_bond_no_directional", None),
    ("directional correction", "pd_ordinary", "pd_ordinary_no_directional", None),
    ("plasticity", "pd_bond_microplastic", "pd_bond", 1.3),
    ("plasticity", "pd_corr_j2", "pd_corr_classical", 1.1),
    ("plasticity", "pd_corr_jc", "pd_corr_classical", 1.1),
    ("correspondence", "pd_corr_classical", "pd_ordinary", 2.0),
    ("correspondence", "pd_corr_extended", "pd_ordinary", 3.0),
    ("legacy mode", "pd_bond_legacy", "pd_bond", None),
    ("legacy mode", "pd_ordinary_legacy", "pd_ordinary", None),
]

# FULL=1: steps per size, about 4e8 bond evaluations (a few seconds of
# Loop time for pd_bond, twice that for pd_ordinary, on today's kernels)
SWEEP_STEPS = {16: 1500, 24: 450, 32: 200, 48: 60, 64: 25}
SWEEP_STYLES = ["pd_bond", "pd_ordinary"]
# the first setup of LAMMPS alone (same ghosts, no pair style): the family
# build is the pd styles' first-setup excess over it
ALONE_STYLE, ALONE_STEPS = "lammps_alone", 1
LEGACY_STEPS = {16: 100, 32: 15}          # peri/ are about 10x slower
LEGACY_STYLES = ["peri_pmb", "peri_lps"]
MEMORY_SIZES, MEMORY_STYLE, MEMORY_BAR = (48, 64), "pd_bond", 35.0
BUILD_BAR = 20.0                           # family build, in steps
BUSY_CPU = 90.0                            # % CPU use below which a run waited for a CPU
MPI_SIZE, MPI_RANKS, MPI_BAR = 48, 2, 0.93
SWEEP_PASSES = 2                           # passes of the sweep
# 2 ranks: 1-rank and 2-rank runs back to back, this many pairs; the bar is
# on the smallest T1 over the smallest T2 (as the throughput tables take the
# smallest pass: a neighbour's load only ever slows a run down)
MPI_PAIRS = 5

# The clock of the block's tables and the sweep's throughput: "cpu" = the
# timed run's CPU time (Loop time x LAMMPS's "% CPU use"), which leaves out
# the time the process waited for a CPU that others were using; "wall" =
# Loop time. The same on a quiet machine. --clock sets it.
CLOCK = "cpu"
CLOCK_NAME = {"cpu": "CPU time", "wall": "Loop time (wall)"}

# ----------------------------------------------------------------- the log

RE_BENCH = re.compile(r"^BENCH (\S+)")
RE_LOOP = re.compile(r"^Loop time of (\S+) on (\d+) procs for (\d+) steps")
RE_BONDS = re.compile(r"^pd/bonds: (\d+) bonds, ")
RE_CPU = re.compile(r"^([0-9.]+)% CPU use with")
RE_BROKEN = re.compile(r"^pd/bonds: \d+ bonds kept, (\d+) of them broken")
RE_PERI_BONDS = re.compile(r"^\s*total # of bonds = (\d+)")
RE_CONTACT = re.compile(r"^pd/contact: list cutoff .*?: ([0-9.]+) neighbours per atom")
RE_FAMILIES = re.compile(r"^pd/bonds: families built in (\S+) s")


def new_record():
    return {"loop": None, "ranks": None, "steps": None, "bonds": None,
            "peri_bonds": None, "broken": None, "contact_nb": None, "cpu": None,
            "families_s": None}


def parse_section(lines, rec):
    """Fill rec from the log lines of one style's runs (the timed run is
    the first one with steps > 0)."""
    for line in lines:
        m = RE_LOOP.match(line)
        if m and int(m.group(3)) > 0 and rec["loop"] is None:
            rec["loop"], rec["ranks"], rec["steps"] = float(m.group(1)), int(m.group(2)), int(m.group(3))
        m = RE_CPU.match(line)
        if m and rec["loop"] is not None and rec["cpu"] is None:
            rec["cpu"] = float(m.group(1))      # the line after the timed run's Loop time
        m = RE_BONDS.match(line)
        if m and rec["bonds"] is None:
            rec["bonds"] = int(m.group(1))
        m = RE_PERI_BONDS.match(line)
        if m and rec["peri_bonds"] is None:
            rec["peri_bonds"] = int(m.group(1)) // 2   # PERI stores each bond twice
        m = RE_BROKEN.match(line)
        if m:
            rec["broken"] = int(m.group(1))
        m = RE_CONTACT.match(line)
        if m:
            rec["contact_nb"] = float(m.group(1))
        m = RE_FAMILIES.match(line)
        if m and rec["families_s"] is None:
            rec["families_s"] = float(m.group(1))     # fix pd/bonds' own timer (slowest rank)
    return rec


def timed(rec):
    """The timed run's time (s) on CLOCK."""
    if CLOCK == "cpu" and rec["cpu"] is not None:
        return rec["loop"] * rec["cpu"] / 100
    return rec["loop"]


def parse_block_log(text):
    """[(style, record)] in the order run, one per BENCH section."""
    sections, style, lines = [], None, []
    for line in text.splitlines() + ["BENCH <end>"]:
        m = RE_BENCH.match(line)
        if m:
            if style:
                sections.append((style, parse_section(lines, new_record())))
            style, lines = m.group(1), []
        else:
            lines.append(line)
    return sections


# ------------------------------------------------------------- the machine

def cpu_line():
    model, ncpu, avx512 = "unknown", 0, False
    try:
        for line in open("/proc/cpuinfo"):
            key, _, val = line.partition(":")
            key = key.strip()
            if key == "model name":
                model, ncpu = val.strip(), ncpu + 1
            elif key == "flags":
                avx512 = "avx512f" in val.split()
    except OSError:
        pass
    return f"{model}, {ncpu} logical CPUs, AVX-512 {'yes' if avx512 else 'no'}"


def cmake_value(cache, key):
    m = re.search(rf"^{re.escape(key)}:\w+=(.*)$", cache, re.M)
    return m.group(1) if m else None


def build_lines(lmp):
    """The build type and compile flags, from the CMake build next to lmp."""
    build = os.path.dirname(lmp)
    try:
        cache = open(os.path.join(build, "CMakeCache.txt")).read()
    except OSError:
        return ["build flags: unknown (no CMakeCache.txt next to the lmp binary)"]
    out = [f"build: {cmake_value(cache, 'CMAKE_BUILD_TYPE') or '?'}, "
           f"C compiler {cmake_value(cache, 'CMAKE_C_COMPILER') or '?'}"]
    options = re.findall(r"^(PDEXT_\w+):(BOOL|STRING)=(.*)$", cache, re.M)
    if options:
        out.append("options: " + ", ".join(f"{k}={v}" for k, _, v in options))
    # the package's own targets (build/CMakeFiles/*.dir) and LAMMPS with its glue
    dirs = [os.path.join(build, "CMakeFiles"), os.path.join(build, "lammps", "CMakeFiles")]
    for top in dirs:
        for target in sorted(os.listdir(top)) if os.path.isdir(top) else []:
            flags = os.path.join(top, target, "flags.make")
            if target != "lmp.dir" and os.path.exists(flags):
                for line in open(flags):
                    if re.match(r"(C|CXX)_FLAGS = ", line):
                        out.append(f"{target.replace('.dir', '')} {line.strip()}")
    return out


def header(lmp, what):
    print(f"PERIDYNAMICS_EXT benchmark, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}: {what}")
    print(f"machine: {cpu_line()}; load average {os.getloadavg()[0]:.2f} at start")
    print(f"lmp: {lmp}")
    for line in build_lines(lmp):
        print(f"  {line}")


# -------------------------------------------------------------- running lmp

def run_lmp(lmp, script, variables, log, ranks=1):
    """Run lmp in bench/; returns (log text, peak RSS of the process tree in
    KiB, wall seconds)."""
    cmd = [lmp, "-in", script, "-echo", "none", "-screen", "none", "-log", log]
    for key, val in variables.items():
        cmd += ["-var", key] + (val if isinstance(val, list) else [str(val)])
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    start = time.time()
    proc = subprocess.Popen(cmd, cwd=HERE, env=MPI_ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    output = proc.stdout.read().decode(errors="replace")
    _, status, usage = os.wait4(proc.pid, 0)   # this child's own rusage
    proc.returncode = os.waitstatus_to_exitcode(status)
    wall = time.time() - start
    text = open(log).read() if os.path.exists(log) else ""
    if proc.returncode != 0:
        sys.exit(f"bench: lmp failed ({proc.returncode}):\n{output[-2000:]}\n{text[-2000:]}")
    return text, usage.ru_maxrss, wall


def mbonds(rec):
    return rec["bonds"] * rec["steps"] / timed(rec) / 1e6 / rec["ranks"]


def ns_per_bond(rec):
    return 1e9 * timed(rec) * rec["ranks"] / (rec["bonds"] * rec["steps"])


def mark(value, bar, at_least, unit="x"):
    """'<= 1.2x ok' or '<= 1.2x MISSED'; '' without a bar."""
    if bar is None:
        return ""
    ok = value >= bar if at_least else value <= bar
    return f"bar {'>=' if at_least else '<='} {bar:g}{unit}: {'ok' if ok else 'MISSED'}"


# --------------------------------------------------------------- the block

def run_block(lmp, outdir, passes):
    styles = BLOCK_STYLES * passes
    text, _, wall = run_lmp(lmp, "in.block", {"style": styles, "steps": BLOCK_STEPS},
                            os.path.join(outdir, "log.block"))
    runs = {}
    for style, rec in parse_block_log(text):
        runs.setdefault(style, []).append(rec)
    best = {}
    for style, recs in runs.items():
        rec = dict(min(recs, key=timed))
        rec["times"] = [timed(r) for r in recs]    # per pass, in order
        best[style] = rec
    fill_legacy_bonds(best)
    return best, wall


def fill_legacy_bonds(best):
    ref = best.get(LEGACY_BONDS_FROM, {}).get("bonds")
    for style, rec in best.items():
        if rec["bonds"] is None and ref:
            if rec["peri_bonds"] not in (None, ref):
                print(f"note: {style} has {rec['peri_bonds']} unique bonds, {LEGACY_BONDS_FROM} {ref}")
            rec["bonds"] = ref


def print_throughput(best, passes):
    print()
    print(f"Throughput (1 rank, {BLOCK_STEPS} steps, {passes} interleaved passes; time = {CLOCK_NAME[CLOCK]} "
          f"of the timed run, the smallest pass)")
    passes_head = " ".join(f"{'pass ' + str(i + 1):>7s}" for i in range(passes))
    print(f"  {'style':26s} {'unique bonds':>12s} {passes_head} {'time (s)':>8s} {'Loop (s)':>8s} "
          f"{'CPU %':>5s} {'M bonds/s':>10s} {'ns/bond':>8s} {'broken':>6s}")
    for style in BLOCK_STYLES:
        rec = best.get(style)
        if not rec:
            continue
        times = " ".join(f"{t:7.3f}" for t in rec["times"])
        broken = "-" if rec["broken"] is None else str(rec["broken"])
        print(f"  {style:26s} {rec['bonds']:12d} {times} {timed(rec):8.3f} {rec['loop']:8.3f} {rec['cpu']:5.1f} "
              f"{mbonds(rec):10.1f} {ns_per_bond(rec):8.2f} {broken:>6s}")
    print("  pass i, time: the time of each pass and the smallest; Loop = LAMMPS's Loop time (wall) of that")
    print("  pass, CPU % its CPU use (below 100: the process waited for a CPU); M bonds/s = million unique")
    print("  bonds per second per core, ns/bond = per bond per step, both from time; broken = bonds broken")
    print("  in the timed run (fix pd/bonds)")
    busy = [s for s, r in best.items() if r["cpu"] is not None and r["cpu"] < BUSY_CPU]
    if busy:
        print(f"  busy machine: {len(busy)} of {len(best)} kept runs used the CPU less than {BUSY_CPU:g}% of "
              "their wall time")


def pass_ratios(num, den):
    return [a / b for a, b in zip(num["times"], den["times"])]


def per_pass(num, den):
    """The ratio in each pass: 'passes 1.02 1.05'."""
    return "passes " + " ".join(f"{r:.2f}" for r in pass_ratios(num, den))


def median_ratio(num, den):
    """The median of the ratios within each pass (a style and its baseline
    run close together in time): less sensitive to one noisy run."""
    r = sorted(pass_ratios(num, den))
    return r[len(r) // 2] if len(r) % 2 else (r[len(r) // 2 - 1] + r[len(r) // 2]) / 2


def print_speedups(best):
    print()
    print("Speed-up over the legacy PERI styles (legacy time / pd time, same block and steps: the")
    print("smallest passes; median = median of the ratios within each pass, listed in brackets;")
    print("the bars are judged on the median)")
    print(f"  {'style':26s}    {'legacy':10s} {'speed-up':>8s} {'median':>7s}")
    for new, old, goal in SPEEDUPS:
        if new in best and old in best:
            ratio, med = timed(best[old]) / timed(best[new]), median_ratio(best[old], best[new])
            print(f"  {new:26s} vs {old:10s} {ratio:7.2f}x {med:6.2f}x   "
                  f"{mark(med, goal, True):24s} ({per_pass(best[old], best[new])})")


def print_effects(best):
    print()
    print("Cost of each effect (time with the effect / time of the baseline: the smallest passes;")
    print("median = median of the ratios within each pass, listed in brackets, on which the bars are")
    print("judged; elastic run, no bond breaks)")
    print(f"  {'effect':22s} {'style':26s} {'baseline':26s} {'cost':>7s} {'median':>7s}")
    for effect, style, base, bar in EFFECTS:
        if style in best and base in best:
            ratio, med = timed(best[style]) / timed(best[base]), median_ratio(best[style], best[base])
            print(f"  {effect:22s} {style:26s} {base:26s} {ratio:6.2f}x {med:6.2f}x   "
                  f"{mark(med, bar, False):24s} ({per_pass(best[style], best[base])})")
    for style, rec in best.items():
        if rec["contact_nb"] is not None:
            print(f"  ({style}: the contact list holds {rec['contact_nb']:g} neighbours per atom, "
                  "cutoff = contact distance + skin)")
    broke = [s for s, r in best.items() if r["broken"]]
    if broke:
        print(f"  WARNING: bonds broke in {', '.join(broke)}: their failure cost is not an elastic run's")


# ---------------------------------------------------------------- FULL=1

def run_size(lmp, outdir, style, n, steps, ranks=1, npass=1):
    tag = f"{style}.{n}.np{ranks}.pass{npass}"
    stamps = os.path.join(outdir, f"stamps.{tag}")
    if os.path.exists(stamps):
        os.remove(stamps)
    text, rss, wall = run_lmp(lmp, "in.size", {"style": style, "n": n, "steps": steps, "stamps": stamps},
                              os.path.join(outdir, f"log.{tag}"), ranks)
    rec = parse_section(text.splitlines(), new_record())
    rec.update(style=style, n=n, rss_kib=rss, wall=wall)
    t = [float(x) for x in open(stamps).read().split()]
    # setup of the first run 0 (families built) minus that of the second (kept)
    rec["build_s"] = (t[1] - t[0]) - (t[2] - t[1])
    return rec


def best_of(runs):
    """One record from the passes of one style and size: the smallest time,
    the smallest family build and Loop time, the largest peak RSS."""
    rec = dict(min(runs, key=timed))
    rec["times"] = [timed(r) for r in runs]
    rec["build_s"] = min(r["build_s"] for r in runs)
    rec["fastest_loop"] = min(r["loop"] for r in runs)
    own = [r["families_s"] for r in runs if r["families_s"] is not None]
    rec["families_steps"] = min(own) / (rec["fastest_loop"] / rec["steps"]) if own else None
    rec["rss_kib"] = max(r["rss_kib"] for r in runs)
    fastest = min(runs, key=lambda r: r["loop"])
    rec["wall"] = (fastest["loop"], fastest["cpu"])      # the smallest Loop time, its CPU use
    return rec


def run_sweep(lmp, outdir, passes):
    """Every size and style once per pass, the passes one after the other."""
    runs = {}
    for npass in range(1, passes + 1):
        for n, steps in SWEEP_STEPS.items():
            todo = [(ALONE_STYLE, ALONE_STEPS)] + [(style, steps) for style in SWEEP_STYLES]
            todo += [(style, LEGACY_STEPS[n]) for style in LEGACY_STYLES if n in LEGACY_STEPS]
            for style, nsteps in todo:
                runs.setdefault((style, n), []).append(run_size(lmp, outdir, style, n, nsteps, 1, npass))
    alone = {n: min(r["build_s"] for r in runs.pop((ALONE_STYLE, n))) for n in SWEEP_STEPS}
    recs = [best_of(r) for r in runs.values()]
    for r in recs:
        r["lammps_s"] = alone[r["n"]]
        r["build_net_s"] = r["build_s"] - r["lammps_s"]
        r["build_steps"] = r["build_net_s"] / (r["fastest_loop"] / r["steps"])
        # the bar: the larger of the two measures of the build
        r["build_bar_steps"] = max(r["build_steps"], r["families_steps"] or 0.0)
    recs.sort(key=lambda r: (r["n"], (SWEEP_STYLES + LEGACY_STYLES).index(r["style"])))
    bonds = {(r["n"], r["style"]): r["bonds"] for r in recs}
    for r in recs:
        if r["bonds"] is None:
            r["bonds"] = bonds.get((r["n"], LEGACY_BONDS_FROM)) or r["peri_bonds"]
    return recs


def print_sweep(recs):
    print()
    print(f"Size sweep (1 rank; each style and size its own lmp process, {SWEEP_PASSES} passes over the list,")
    print(f"the smallest {CLOCK_NAME[CLOCK]} kept: M bonds/s and ns/bond from it)")
    print(f"  {'style':12s} {'size':>5s} {'atoms':>7s} {'unique bonds':>12s} {'steps':>5s} {'Loop (s)':>8s} "
          f"{'CPU %':>5s} {'M bonds/s':>10s} {'ns/bond':>8s} {'setups (s)':>10s} {'LAMMPS (s)':>10s} "
          f"{'build (steps)':>13s} {'timer (steps)':>13s} "
          f"{'peak RSS (MiB)':>14s} {'bytes/bond':>10s}")
    for r in recs:
        atoms = r["n"] ** 3
        print(f"  {r['style']:12s} {str(r['n']) + '^3':>5s} {atoms:7d} {r['bonds']:12d} {r['steps']:5d} "
              f"{r['loop']:8.3f} {r['cpu']:5.1f} {mbonds(r):10.1f} {ns_per_bond(r):8.2f} {r['build_s']:10.3f} "
              f"{r['lammps_s']:10.3f} {r['build_steps']:13.1f} {r['families_steps'] or float('nan'):13.1f} "
              f"{r['rss_kib'] / 1024:14.1f} {1024 * r['rss_kib'] / r['bonds']:10.1f}")
    print("  Loop, CPU %: the wall-clock Loop time of the kept pass and its CPU use. setups = setup of the")
    print("  first 'run 0' (families built) minus setup of a second one (families kept), wall clock, the")
    print("  smaller of the passes; LAMMPS = the same for LAMMPS alone (pairs/lammps_alone.in: no pair style,")
    print("  the same ghosts and sorting), what any first setup costs; build (steps) = (setups - LAMMPS) /")
    print("  (smallest Loop time / steps); timer (steps) = fix pd/bonds' own 'families built in' time in")
    print(f"  steps. The bar (<= {BUILD_BAR:g} steps) takes the larger of the two.")
    print("  peak RSS = max resident set of the whole lmp process (os.wait4), bytes/bond = peak RSS / unique bonds")
    by = {(r["style"], r["n"]): r for r in recs}
    print()
    print("Sweep bars")
    for n in MEMORY_SIZES:
        r = by.get((MEMORY_STYLE, n))
        if r:
            per_bond = 1024 * r["rss_kib"] / r["bonds"]
            print(f"  peak memory per bond, {MEMORY_STYLE} {n}^3: {per_bond:6.1f} bytes   "
                  f"{mark(per_bond, MEMORY_BAR, False, ' bytes')}")
    for style in SWEEP_STYLES:
        worst = max((r for r in recs if r["style"] == style), key=lambda r: r["build_bar_steps"])
        own = (f"   (the larger of: fix pd/bonds' own timer {worst['families_steps']:.1f}, "
               f"the first setup's excess over LAMMPS alone {worst['build_steps']:.1f})"
               if worst["families_steps"] is not None else "")
        print(f"  family build, {style}, worst size ({worst['n']}^3): {worst['build_bar_steps']:6.1f} steps   "
              f"{mark(worst['build_bar_steps'], BUILD_BAR, False, ' steps')}{own}")
    for new, old, goal in SPEEDUPS:
        for n in LEGACY_STEPS:
            if (new, n) in by and (old, n) in by:
                ratio = mbonds(by[(new, n)]) / mbonds(by[(old, n)])
                print(f"  {new} vs {old} at {n}^3 (M bonds/s ratio): {ratio:6.2f}x   {mark(ratio, goal, True)}")


def run_mpi(lmp, outdir):
    """The styles of the sweep at MPI_SIZE on 1 and on MPI_RANKS ranks, back to
    back, MPI_PAIRS times: [(style, [(1-rank record, MPI_RANKS-rank record)])]."""
    rows = []
    for style in SWEEP_STYLES:
        pairs = [tuple(run_size(lmp, outdir, style, MPI_SIZE, SWEEP_STEPS[MPI_SIZE], ranks, f"pair{p}")
                       for ranks in (1, MPI_RANKS)) for p in range(1, MPI_PAIRS + 1)]
        rows.append((style, pairs))
    return rows


def print_mpi(rows):
    print()
    print(f"{MPI_RANKS}-rank efficiency at {MPI_SIZE}^3 (mpirun -np {MPI_RANKS}; {MPI_PAIRS} pairs of a 1-rank and a "
          f"{MPI_RANKS}-rank run, back to back,")
    print(f"same steps): T1 / ({MPI_RANKS} T{MPI_RANKS}) of the smallest wall-clock Loop times; each pair's in brackets")
    busy = False
    for style, pairs in rows:
        one = min((a for a, _ in pairs), key=lambda r: r["loop"])
        two = min((b for _, b in pairs), key=lambda r: r["loop"])
        eff = one["loop"] / (MPI_RANKS * two["loop"])
        effs = sorted(a["loop"] / (MPI_RANKS * b["loop"]) for a, b in pairs)
        busy |= any(min(a["cpu"], b["cpu"]) < BUSY_CPU for a, b in pairs)
        print(f"  {style:12s} T1 {one['loop']:7.3f} s ({one['cpu']:5.1f}% CPU)  "
              f"T{MPI_RANKS} {two['loop']:7.3f} s ({two['cpu']:5.1f}% CPU)  efficiency {100 * eff:5.1f}%   "
              f"{mark(100 * eff, 100 * MPI_BAR, True, '%')}   (pairs "
              + " ".join(f"{100 * e:.1f}%" for e in effs) + f"; median {100 * effs[len(effs) // 2]:.1f}%)")
    print(f"  (a neighbour's load slows a {MPI_RANKS}-rank run when it takes either core: the smallest times are")
    print("  the code's, the pairs' spread is the machine's)")
    if busy:
        print(f"  busy machine: a CPU use below {BUSY_CPU:g}% means the ranks waited for CPUs that others used;")
        print("  this efficiency then measures the load more than the code: run it again on a quiet machine")


# -------------------------------------------------------------------- main

def main():
    global CLOCK
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--full", action="store_true", help="add the size sweep, memory and 2 ranks")
    ap.add_argument("--passes", type=int, default=3, help="interleaved passes over the block's styles")
    ap.add_argument("--clock", choices=("cpu", "wall"), default=CLOCK,
                    help="the time of the tables: the timed run's CPU time (default) or its Loop time")
    ap.add_argument("--logs", help="keep the LAMMPS logs here (default: a new temporary directory)")
    args = ap.parse_args()
    if args.passes < 1:
        ap.error(f"--passes {args.passes}: expected a whole number of passes, at least 1")
    CLOCK = args.clock
    lmp = os.path.realpath(args.lmp)
    outdir = args.logs or tempfile.mkdtemp(prefix="pdext-bench-")
    os.makedirs(outdir, exist_ok=True)
    what = ("benchmark block 16^3 (4096 atoms, 122 bonds per atom), 1 rank, 1 core"
            + ("; size sweep 16^3-64^3 and 2 ranks" if args.full else ""))
    header(lmp, what)
    start = time.time()
    best, wall = run_block(lmp, outdir, args.passes)
    print_throughput(best, args.passes)
    print_speedups(best)
    print_effects(best)
    print(f"(block: {wall:.0f} s of wall time in one lmp process)")
    if args.full:
        sweep_start = time.time()
        recs = run_sweep(lmp, outdir, SWEEP_PASSES)
        print_sweep(recs)
        print_mpi(run_mpi(lmp, outdir))
        print(f"(sweep and 2 ranks: {time.time() - sweep_start:.0f} s of wall time)")
    print()
    print(f"total {time.time() - start:.0f} s; load average {os.getloadavg()[0]:.2f} at the end; "
          f"LAMMPS logs in {outdir}")


if __name__ == "__main__":
    main()
