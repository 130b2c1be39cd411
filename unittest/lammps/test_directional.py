"""directional_correction yes (core/pd_directional.h): each family's fourth
moment made isotropic by a quartic form of the bond direction.

A uniform strain then gives the classical constants in every mode (the
accuracy report's constants deck: 3 axial strains, the simple shears, the
45-degree shear, dilatation; energy and virial stress): on the simple
cubic, fcc and square lattices exactly (to the +-eps averaging's O(eps^2),
1e-8), where without it pd/bond is 2.4-13.7% and pd/ordinary 1.5-10% off
in shear; on jittered arrangements (every particle moved by up to 0.2
spacings) within 0.5% (measured 0.01-0.23%): each family's form is exact
for it, but a bond's weight takes the mean of its two ends' forms, and
neighbouring irregular families differ. The hexagonal lattice is
isotropic already: every factor is 1.

A lattice's complete families take one sampled family's form (only the
others fit their own): a periodic lattice fits none of its own, and two
bodies of one type on lattices turned 45 degrees apart give each body's
deep interior the per-atom energy it has alone (the turned lattice's
families have other eighth moments: taking the first one's form would put
its energy off by several per cent), on 1 and 2 ranks.

The weights are scaled once, by the run that builds the families: a
restart file keeps them (the continued run's energy is the first's to
round-off, and it scales nothing), and 2 ranks give 1 rank's energy. A
family too irregular for the fit (its own form would make a bond's factor
negative) is moved toward f = 1 until its smallest factor is 0.25, and the
log counts those atoms."""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "accuracy"))
from lmptest import LMP, check, check_le, finish, read_dump, run, workdir  # noqa: E402
import deck  # noqa: E402
import q_constants  # noqa: E402

H = 1.0e-3


def constants_error(case):
    return q_constants.measure(dict(case, ratio=3, directional=True), LMP, workdir())["err"]


for lattice in ("sc", "fcc", "square"):
    for style, extra in (("pd/bond", {"quadrature": "point"}), ("pd/bond", {"quadrature": "partial"}),
                         ("pd/ordinary", {"m": 0.5}), ("pd/ordinary", {"m": -1, "quadrature": "partial"})):
        if lattice == "fcc" and extra.get("quadrature") == "partial":
            continue    # (the slowest block; sc and square cover partial cells)
        err = constants_error(dict({"style": style, "lattice": lattice}, **extra))
        check_le(f"{lattice}, {style} {extra}: every mode's constants classical", err, 1e-6,
                 "isotropic fourth moment; +-1e-4 strains averaged leave O(eps^2)")

for lattice in ("sc-jitter", "square-jitter"):
    for style in ("pd/bond", "pd/ordinary"):
        err = constants_error({"style": style, "lattice": lattice, "quadrature": "point"})
        check_le(f"{lattice}, {style}: every mode's constants within 0.5%", err, 0.005,
                 "each family exact, a bond takes the mean of its ends' forms (measured 0.01-0.23%)")


def block(lattice, style, extra=""):
    """A periodic block in shear, its pe printed; the log."""
    text, _, lengths = deck.periodic_block(lattice, H, 8 * H)
    text += deck.pair_lines({"style": style, "lattice": lattice, "ratio": 3, "directional": True}, H)
    e = q_constants.modes(deck.dims_of(lattice))["shear_45"]
    text += "run 0\n" + q_constants.box_change(e, lengths)    # families built in the reference box
    text += 'thermo_modify format float %.17g\nrun 0\nprint "PE $(pe:%.17g)"\n' + extra
    return text


def pe(out):
    return float(deck.printed(out, "PE")[-1][0])


def factors(out):
    m = re.search(r"directional correction: .* bond weights scaled by ([0-9.]+) \.\. ([0-9.]+)", out)
    return (float(m.group(1)), float(m.group(2))) if m else None


out, _ = run(block("hex", "pd/ordinary"), workdir())
check("hex: every factor 1 (isotropic already)", factors(out) == (1.0, 1.0), f"log: {factors(out)}")
out, _ = run(block("square", "pd/ordinary"), workdir())
lo, hi = factors(out) or (0, 0)
check("square: the log reports the factors' range", 0.8 < lo < 1.0 < hi < 1.2, f"{lo} .. {hi}")
own_fits = re.search(r"\((\d+) atoms fitted on their own family", out)
check("square, periodic: every family takes the sampled one's form, none fits its own",
      own_fits is not None and int(own_fits.group(1)) == 0, own_fits.group(0) if own_fits else "no such line")

predicted = re.search(r"lattice error of the constants on sq, .* point quadrature, directional correction: "
                      r"dilatation (\S+), shear along the lattice axes (\S+), simple shear xy (\S+)\n", out)
check("square: the setup report predicts the corrected family's constants (every mode 0%)",
      predicted is not None and predicted.groups() == ("0%", "0%", "0%"),
      predicted.group(0).strip() if predicted else "no such line")

# a family too irregular for the quartic fit (jittered, 2.5 spacings, the
# tupek influence vanishing at the horizon: some own fits are negative
# along a bond) is corrected only partly, every factor at least the floor
text, _, lengths = deck.periodic_block("square-jitter", H, 8 * H)
text += deck.pair_lines({"style": "pd/ordinary", "lattice": "square-jitter", "ratio": 2.5, "influence": "tupek"}, H)
out, _ = run(text + "run 0\n", workdir())
m = re.search(r"bond weights scaled by ([0-9.]+) \.\. [0-9.]+; (\d+) atoms' families too irregular", out)
check("irregular families: the run goes on, the log names the atoms corrected only partly, and no factor is "
      "below the floor", m is not None and int(m.group(2)) > 0 and float(m.group(1)) >= 0.25 - 5e-4,
      m.group(0) if m else "no such line")


def grains(which):
    """Square-lattice plates of one type, 'a' along the axes and 'b' turned
    45 degrees, 10 spacings apart (no bond between them), sheared and
    stretched uniformly after the build; each atom's x, y and energy."""
    body = {"a": ("0", "20"), "b": ("30", "50")}
    text = deck.header("square", H, "f f p")
    text += f"region box block {-2 * H!r} {52 * H!r} {-2 * H!r} {22 * H!r} {-0.5 * H!r} {0.5 * H!r} units box\n"
    text += "create_box 1 box\n"
    for g in which:
        lo, hi = (float(v) * H for v in body[g])
        orient = " orient x 1 1 0 orient y -1 1 0 orient z 0 0 1" if g == "b" else ""
        text += (f"lattice sq {H!r}{orient}\n"
                 f"region {g} block {lo!r} {hi!r} 0 {20 * H!r} {-0.5 * H!r} {0.5 * H!r} units box\n")
        text += f"create_atoms 1 region {g}\n"
    text += f"set group all density {deck.material()['density']}\nset group all volume {deck.volume('square', H)!r}\n"
    text += deck.pair_lines({"style": "pd/ordinary", "lattice": "square", "ratio": 3}, H)
    text += ("run 0\nvariable dx atom 2e-3*x+1e-3*y\nvariable dy atom 1e-3*x-5e-4*y\n"
             "displace_atoms all move v_dx v_dy 0 units box\ncompute e all pe/atom\n"
             # (a dump of the run itself: LAMMPS 2021's write_dump refuses a
             # per-atom energy after the run)
             "dump d all custom 1 grains.dump id x y c_e\ndump_modify d format float %.17g\nrun 0\n")
    return text


def deep_energies(which, ranks=1):
    """{(x, y) rounded to 0.01 spacing: energy} of the atoms 7 spacings or
    more inside either body's region (their partners' families are
    complete too), the log and the number of atoms."""
    d = workdir()
    out, _ = run(grains(which), d, ranks=ranks)
    atoms = read_dump(os.path.join(d, "grains.dump")) if os.path.exists(os.path.join(d, "grains.dump")) else {}
    deep = {}
    for x, y, e in atoms.values():
        u, v = x / H, y / H
        inside = (7 <= u <= 13 or 37 <= u <= 43) and 7 <= v <= 13
        if inside:
            deep[(round(u, 2), round(v, 2))] = e
    return deep, out, len(atoms)


alone_a, _, _ = deep_energies("a")
alone_b, _, _ = deep_energies("b")
together, out, natoms = deep_energies("ab")
two, _, _ = deep_energies("ab", ranks=2)
alone = {**alone_a, **alone_b}
spread = max(abs(e / alone[k] - 1) for k, e in together.items()) if together.keys() == alone.keys() else math.inf
own_fits = re.search(r"\((\d+) atoms fitted on their own family", out)
check("two bodies turned 45 degrees apart: some families fit their own form, some take the sample's",
      own_fits is not None and 0 < int(own_fits.group(1)) < natoms,
      own_fits.group(0) if own_fits else "no such line")
check_le(f"two bodies turned 45 degrees apart: each deep interior atom's energy as alone ({len(together)} atoms)",
         spread, 1e-9, "the same forms; round-off of sums in another order")
spread2 = max(abs(e / together[k] - 1) for k, e in two.items()) if two.keys() == together.keys() else math.inf
check_le("two bodies turned 45 degrees apart, 2 ranks: 1 rank's energies", spread2, 1e-9, "round-off")

# restart: the scaled weights are kept, not scaled again
d = workdir()
first, _ = run(block("sc", "pd/bond", "write_restart block.restart\n"), d)
again, _ = run("read_restart block.restart\nthermo_modify format float %.17g\nrun 0\n"
               'print "PE $(pe:%.17g)"\n', d, name="in.again")
check_le("restart: the continued run's energy is the first's", abs(pe(again) / pe(first) - 1), 1e-12, "round-off")
check("restart: nothing scaled again", factors(first) is not None and factors(again) is None)

# ranks
one, _ = run(block("sc-jitter", "pd/ordinary"), workdir())
two, _ = run(block("sc-jitter", "pd/ordinary"), workdir(), ranks=2)
check_le("2 ranks: 1 rank's energy", abs(pe(two) / pe(one) - 1), 1e-12, "round-off of the sums' order")

# bad input
for settings, expect in (("pd/corr model elastic directional_correction yes", "is for pd/bond and pd/ordinary"),
                         ("pd/ordinary legacy directional_correction yes", "do not go together"),
                         ("pd/bond directional_correction maybe", "expected yes or no")):
    out, _ = run("units si\natom_style peri\nregion b block 0 1 0 1 0 1\ncreate_box 1 b\n"
                 f"pair_style {settings}\n", workdir(), expect_error=True)
    check(f"'{settings}': an ERROR that says so", "ERROR" in out and expect in out,
          out.strip().splitlines()[-1] if out.strip() else "")
finish()
