"""The target: the prepare deck runs once and writes the restart.

It runs again only when the restart is missing, older than the prepare
deck, or was made with other [variables] (kept in <out>/target.vars)."""
import os
import time

import failures
import launch
from campaign_file import CampaignError


def stamp(c):
    return "".join(f"{n} {v}\n" for n, v in sorted(c.variables.items()))


def why_needed(c, force=False):
    """Why the prepare deck must run, or None if the restart is current."""
    if not c.prepare:
        return None
    if force:
        return "asked for (--prepare)"
    if not os.path.isfile(c.restart):
        return "no restart yet"
    if os.path.getmtime(c.restart) < os.path.getmtime(c.prepare):
        return f"{os.path.basename(c.prepare)} is newer than the restart"
    vars_file = os.path.join(c.out, "target.vars")
    if os.path.isfile(vars_file) and open(vars_file).read() != stamp(c):
        return "[variables] changed"
    return None


def run(c, lmp, ranks, mpirun, lock_fd, say):
    """Run the prepare deck on the ranks of one case (atom IDs from
    create_atoms depend on the rank count, so the target, and every result,
    does not depend on the number of partitions); CampaignError if it fails
    or writes no restart."""
    os.makedirs(os.path.join(c.out, "logs"), exist_ok=True)
    log = os.path.join(c.out, "logs", "prepare.log")
    cmd = launch.command(lmp, c.rel(c.prepare), c.rel(log), ranks=ranks, mpirun=mpirun)
    for n, v in [("restart", c.rel(c.restart))] + sorted(c.variables.items()):
        cmd += ["-var", n, v]
    start = time.time()
    if os.path.exists(c.restart):
        os.remove(c.restart)
    rc = launch.run(cmd, c.home, os.path.join(c.out, "prepare.out"), lock_fd)
    if rc != 0:
        e = failures.error_of(log) or failures.error_of(os.path.join(c.out, "prepare.out"))
        raise CampaignError(f"the prepare deck {c.rel(c.prepare)} failed (exit {rc}): "
                            f"{e or 'no ERROR in its log'}  (log: {c.rel(log)}, "
                            f"output: {c.rel(os.path.join(c.out, 'prepare.out'))})")
    if not os.path.isfile(c.restart):
        raise CampaignError(f"the prepare deck {c.rel(c.prepare)} ran but wrote no restart "
                            f"{c.rel(c.restart)}: end it with 'write_restart ${{restart}}'")
    with open(os.path.join(c.out, "target.vars"), "w") as f:
        f.write(stamp(c))
    say(f"prepared {c.rel(c.restart)} in {time.time() - start:.1f} s")
