"""pd/contact's short list and cached candidates.

pd/contact takes its candidates (pairs that may touch, with their contact
distances) when LAMMPS reneighbors, and visits at each step only a short
list: the candidates within contact distance + a skin of its own, taken
again when an atom of a candidate has moved more than half that skin.
That must change nothing: the forces are those of checking every candidate
at every step ('skin 0'), summed in the same order, so the runs agree bit
for bit (tolerance 1e-12 relative).

- Two blocks that were never bonded collide (pd/ordinary + pd/contact,
  periodic in y and z, so pairs reach ghost atoms): they start 2 mm apart,
  farther than the list's cutoff (1.5 mm), LAMMPS reneighbors when they
  are 1 mm apart, and they approach the contact distance (0.5 mm) from
  beyond the short list's skin. Default skin, a tiny skin (the short list is taken again almost
  every step) and no short list give the same final positions; with
  friction too (an oblique collision); and on 2 ranks with the tiny skin
  as on 1 rank (round-off).
- Legacy mode: the same collision with pd/bond legacy + pd/contact legacy
  against peri/pmb, with several reneighborings during the run and PERI's
  short-range forces doing the rebound (without them the blocks pass
  through each other): positions agree to 1e-10 relative (round-off of
  differently ordered sums), and the short list agrees with 'skin 0' bit
  for bit."""
from lmptest import *

d = workdir()


def blocks(pairs, steps, v=20.0, vy=0.0, timestep=2e-8, tag="x", extra="", b0=10, va=None):
    return two_blocks(b0) + f"""set group all density 2200
set group all volume {VOLUME}
{extra}{pairs}
velocity a set {v if va is None else va} {vy} 0 units box
velocity b set {-v} {-vy} 0 units box
variable gap equal bound(b,xmin)-bound(a,xmax)
fix 1 all nve
timestep {timestep}
thermo 50
thermo_style custom step pe ke v_gap
run {steps}
write_dump all custom {tag} id xu yu zu vx vy vz modify sort id format float %.17g
"""


def builds(out):
    return log_value(out, r"Neighbor list builds = ([0-9]+)")


def compare(what, tags, tolerance=1e-12, reason="the same pairs in the same order"):
    ref = read_dump(f"{d}/{tags[0]}")
    for tag in tags[1:]:
        check_le(f"{what}: {tag} as {tags[0]}", max_rel_diff(ref, read_dump(f"{d}/{tag}")), tolerance, reason)


# -- pd/ordinary + pd/contact: the short list against every candidate --
CONTACT = ("pair_style hybrid/overlay pd/ordinary pd/contact{opts}\n"
           f"pair_coeff * * pd/ordinary E 3.5e9 nu 0.25 horizon {HORIZON}\npair_coeff * * pd/contact\n")
runs = {"default": "", "skin0": " skin 0", "tiny": " skin 1e-6"}
for tag, opts in runs.items():
    out, rows = run(blocks(CONTACT.format(opts=opts), 2600, tag=tag, b0=9), d)
    if tag == "default":
        cutoff_nb = log_value(out, r"([0-9.]+) neighbours per atom, ")
        short_nb = log_value(out, r"short list \(skin [0-9.e+-]+\): ([0-9.]+) neighbours per atom")
        check("the log reports both lists (neighbours per atom)", short_nb == short_nb and short_nb <= cutoff_nb,
              f"list {cutoff_nb}, short list {short_nb}")
        check("the blocks start farther apart than the list's cutoff and reneighbor on the way",
              rows[0]["v_gap"] > 0.0015 and builds(out) >= 1, f"{builds(out):.0f} builds")
        check("the blocks rebound", rows[-1]["v_gap"] > min(r["v_gap"] for r in rows) + 1e-4)
    if tag == "skin0":
        check("'skin 0' is logged", "no short list (skin 0)" in out)
compare("contact", list(runs))

# friction: the velocities of the pairs in the short list
for tag, opts in (("fr_default", " friction 0.5"), ("fr_skin0", " friction 0.5 skin 0"),
                  ("fr_tiny", " friction 0.5 skin 1e-6")):
    run(blocks(CONTACT.format(opts=opts), 2600, vy=10.0, tag=tag, extra="comm_modify vel yes\n", b0=9), d)
compare("friction", ["fr_default", "fr_skin0", "fr_tiny"])
check("friction acted (the run differs from the frictionless one)",
      max_rel_diff(read_dump(f"{d}/fr_default"), read_dump(f"{d}/default")) > 1e-3)

# 2 ranks: each takes its own short list over owned and ghost atoms
run(blocks(CONTACT.format(opts=" skin 1e-6"), 2600, tag="tiny2", b0=9), d, ranks=2)
compare("2 ranks", ["default", "tiny2"], 1e-10, "round-off")
# block A at rest, B at 40 m/s: on 2 ranks (split along x) the pairs across
# the ranks' boundary are kept by A's rank, where B's atoms are ghosts: only
# the ghosts' motion can bring them into contact there
for tag, opts, ranks in (("still_skin0", " skin 0", 1), ("still_tiny2", " skin 1e-6", 2)):
    run(blocks(CONTACT.format(opts=opts), 2600, v=40.0, va=0.0, tag=tag, b0=9), d, ranks=ranks)
compare("moving ghosts, 2 ranks", ["still_skin0", "still_tiny2"], 1e-10, "round-off")

# -- legacy: PERI's short-range forces through reneighborings --
LEGACY = ("pair_style hybrid/overlay pd/bond legacy pd/contact legacy{opts}\n"
          f"pair_coeff * * pd/bond pmb c {MICROMODULUS!r} horizon {HORIZON}\npair_coeff * * pd/contact\n")
PERI = f"pair_style peri/pmb\npair_coeff * * {MICROMODULUS!r} {HORIZON} 100.0 0.0\n"    # never breaks
NONE = f"pair_style pd/bond legacy\npair_coeff * * pmb c {MICROMODULUS!r} horizon {HORIZON}\n"


def one_type(script):
    """PERI's contact acts between atoms of the pair's type: both blocks
    get type 1 (no bonds join them, the gap exceeds the horizon)."""
    return replace_exact(replace_exact(script, "create_atoms 2 region b", "create_atoms 1 region b"),
                         "group a type 1\ngroup b type 2", "group a region a\ngroup b region b")


for tag, pairs in (("peri", PERI), ("leg_default", LEGACY.format(opts="")), ("leg_skin0", LEGACY.format(opts=" skin 0")),
                   ("leg_tiny", LEGACY.format(opts=" skin 2e-5")), ("leg_none", NONE)):
    out, rows = run(one_type(blocks(pairs, 600, v=50.0, timestep=1e-7, tag=tag)), d)
    if tag == "leg_default":
        check("legacy: reneighboring during the run", builds(out) >= 3, f"{builds(out):.0f} builds")
        check("legacy: the blocks rebound", rows[-1]["v_gap"] > 0.002)
    if tag == "leg_none":
        check("legacy: without the short-range forces the blocks pass through each other",
              min(r["v_gap"] for r in rows) < 0)
compare("legacy", ["leg_default", "leg_skin0", "leg_tiny"])
compare("legacy parity", ["peri", "leg_default"], 1e-10, "PERI's arithmetic, sums in another order")

for what, opts, message in (("negative skin", " skin -1e-4", "skin must be a finite number >= 0, got '-1e-4'"),
                            ("skin without a value", " skin", "'skin' needs a value")):
    out, _ = run(blocks(CONTACT.format(opts=opts), 0), d, expect_error=True)
    check(f"bad input, {what}: ERROR names it", message in out)
finish()
