#!/usr/bin/env python3
"""Run a campaign: a target prepared once, many cases from its restart,
one CSV row per case (doc/campaign.md).

  pd_campaign.py CAMPAIGN.ini [-p PARTITIONS] [-k RANKS] [--lmp PATH]
                 [--mpirun CMD] [--prepare] [--keep-going] [--status]

Runs the prepare deck if the restart is not current, then every case that
has no complete result file, in one lmp run on PARTITIONS partitions of
RANKS ranks (LAMMPS's uloop hands cases to free partitions). Run it again
after an interruption: finished cases are kept."""
import argparse
import os
import shutil
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import campaign_file  # noqa: E402
import failures  # noqa: E402
import launch  # noqa: E402
import loop_deck  # noqa: E402
import plot  # noqa: E402
import prepare  # noqa: E402
import results  # noqa: E402
from campaign_file import CampaignError, key  # noqa: E402
from progress import Progress, hms  # noqa: E402


def say(msg):
    print(f"pd_campaign: {msg}", flush=True)


def find_lmp(given):
    """--lmp, else $PDEXT_LMP, else the project's build/lmp, else lmp on PATH."""
    if given:
        if os.path.isfile(given) and os.access(given, os.X_OK):
            return os.path.abspath(given)
        raise CampaignError(f"--lmp {given}: no such executable")
    here = os.path.dirname(os.path.abspath(__file__))
    for p in (os.environ.get("PDEXT_LMP"), os.path.join(here, "../../build/lmp"), shutil.which("lmp")):
        if p and os.path.isfile(p) and os.access(p, os.X_OK):
            return os.path.abspath(p)
    raise CampaignError("no LAMMPS binary: give --lmp PATH (or set PDEXT_LMP)")


def arguments(argv):
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("campaign", help="the campaign file (INI)")
    a.add_argument("-p", "--partitions", type=int, default=1, help="cases run side by side (default 1)")
    a.add_argument("-k", "--ranks", type=int, default=1, help="MPI ranks per case (default 1)")
    a.add_argument("--lmp", help="LAMMPS binary (default $PDEXT_LMP, build/lmp, lmp on PATH)")
    a.add_argument("--mpirun", default="mpirun", help="MPI launcher command (default mpirun)")
    a.add_argument("--prepare", action="store_true", help="run the prepare deck even if the restart is current")
    a.add_argument("--keep-going", action="store_true",
                   help="after a failed case, run the others (failed cases are retried at the next start)")
    a.add_argument("--status", action="store_true", help="print what is done and pending; run nothing")
    args = a.parse_args(argv)
    if args.partitions < 1 or args.ranks < 1:
        a.error("--partitions and --ranks must be at least 1")
    return args


def not_before(c):
    """Results older than the target restart were made from another target."""
    return os.path.getmtime(c.restart) if c.restart and os.path.isfile(c.restart) else 0.0


def status(c):
    done = results.scan(c, not_before(c))
    say(f"{c.where()}: {len(done)}/{len(c.cases)} cases done")
    for case in c.cases:
        print(f"  {'done   ' if key(case) in done else 'pending'} {key(case)}")
    return 0


def run_cases(c, args, lmp, fd):
    """Launch lmp until every case is done or one fails; returns {key: failure}."""
    failed, isolate = {}, None
    done = results.scan(c, not_before(c))
    stale = sum(1 for case in c.cases if key(case) not in done and os.path.isfile(results.path(c, case)))
    if stale:
        say(f"{stale} result file(s) are incomplete or older than the target restart: those cases run again")
    results.write_csv(c, done)
    if done:
        say(f"{len(done)}/{len(c.cases)} cases done earlier (their result files are kept)")
    progress = Progress(len(c.cases), len(done), say)
    while True:
        pending = isolate or [case for case in c.cases if key(case) not in done and key(case) not in failed]
        if not pending:
            return failed
        parts = 1 if isolate else min(args.partitions, len(pending))
        isolate = None
        deck = loop_deck.write(c, pending, parts)
        logs = os.path.join(c.out, "logs")
        output = os.path.join(c.out, "lmp.out")
        cmd = launch.command(lmp, c.rel(deck), c.rel(os.path.join(logs, "lmp.log")), parts, args.ranks,
                             args.mpirun, plog=c.rel(os.path.join(logs, "partition.log")))
        say(f"{len(done)}/{len(c.cases)} done; running {len(pending)} on {parts} partition(s) x "
            f"{args.ranks} rank(s): {' '.join(cmd)}")

        def poll():
            now = results.scan(c, not_before(c))
            fresh = [k for k in now if k not in done]
            if fresh:
                done.update(now)
                results.write_csv(c, done)
                for k in fresh:
                    progress.case_done(k, now[k], c.results)

        since = time.time()
        launch.clear_uloop(c.home)
        try:
            rc = launch.run(cmd, c.home, output, fd, poll)
        finally:
            poll()
            launch.clear_uloop(c.home)
        left = [case for case in pending if key(case) not in done]
        if rc == 0 and not left:
            continue
        bad = failures.failed(c, left, since, parts, output)
        if bad is None:
            isolate = failures.started(c, left, since)
            say(f"lmp stopped (exit {rc}) while {len(isolate)} case(s) ran and no ERROR reached their logs: "
                "running them again one at a time to find the one that fails")
            continue
        if not bad:
            tail = open(output, errors="replace").read().splitlines()[-5:]
            raise CampaignError(f"lmp stopped (exit {rc}) with {len(left)} case(s) not done and no ERROR "
                                f"in their logs; last output ({c.rel(output)}):\n  " + "\n  ".join(tail))
        for case, msg in bad:
            failed[key(case)] = msg
            say(f"case {key(case)} FAILED: {msg}")
        if not args.keep_going:
            return failed


def main(argv=None):
    args = arguments(argv)
    start = time.time()
    try:
        c = campaign_file.load(args.campaign)
        if args.status:
            return status(c)
        lmp = find_lmp(args.lmp)
        for d in ("results", "logs"):
            os.makedirs(os.path.join(c.out, d), exist_ok=True)
        fd = launch.lock(c.home)
        why = prepare.why_needed(c, args.prepare)
        if why:
            say(f"preparing the target ({why}): {c.rel(c.prepare)} -> {c.rel(c.restart)}")
            prepare.run(c, lmp, args.ranks, args.mpirun, fd, say)
        elif c.restart and not os.path.isfile(c.restart):
            raise CampaignError(f"{c.where()}: the restart {c.rel(c.restart)} does not exist and no prepare "
                                "deck makes it (prepare = in.prepare in [campaign])")
        failed = run_cases(c, args, lmp, fd)
    except (CampaignError, RuntimeError) as e:       # RuntimeError: the folder is locked
        print(f"pd_campaign: error: {e}", file=sys.stderr)
        return 2
    except launch.Interrupted as e:
        done = results.scan(c, not_before(c))
        results.write_csv(c, done)
        say(f"interrupted ({e}) after {hms(time.time() - start)}: {len(done)}/{len(c.cases)} done; "
            "run the same command again to resume")
        return 130
    done = results.scan(c, not_before(c))
    csv_file = results.write_csv(c, done)
    say(f"{len(done)}/{len(c.cases)} cases done in {hms(time.time() - start)}: {c.rel(csv_file)}")
    if c.plot and done:
        say(plot.draw(c, done))
    if failed:
        say(f"{len(failed)} case(s) failed; fix them and run the same command again "
            "(finished cases are kept)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
