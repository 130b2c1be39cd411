"""Which case made a launch fail, and why.

An ERROR in one partition aborts every partition (LAMMPS calls
MPI_Abort), and MPI_Abort flushes no file: a case's log may end before its
ERROR. What stays: the logs' existence (a case that started in this launch
has one), <case>.missing (written before the ERROR, with the results the
case deck did not define) and, on one partition, the line-buffered screen
output (launch.command). With one partition one case runs at a time, so
the case that failed is the one started and not finished; with several,
an ERROR that did not reach a log leaves the culprit ambiguous, and the
driver runs those cases again one at a time to find it."""
import os

import results
from campaign_file import key


def log_path(c, case):
    return os.path.join(c.out, "logs", key(case) + ".log")


def error_of(text_file):
    """The last ERROR line of a LAMMPS log or screen output (with the
    command that raised it), or None."""
    try:
        lines = open(text_file, errors="replace").read().splitlines()
    except OSError:
        return None
    for i in range(len(lines) - 1, -1, -1):
        if lines[i].startswith("ERROR"):
            last = next((m for m in lines[i + 1:i + 3] if m.startswith("Last command:")), "")
            return (lines[i] + ("; " + last if last else "")).strip()
    return None


def started(c, cases, since):
    """The cases whose log was opened since `since` (in this launch)."""
    return [case for case in cases
            if os.path.isfile(log_path(c, case)) and os.path.getmtime(log_path(c, case)) >= since]


def missing_message(c, names):
    return (f"the case deck {os.path.basename(c.case)} leaves no variable {', '.join(names)} defined, "
            f"but {c.where()} names {'it' if len(names) == 1 else 'them'} in results: define each "
            "result at the end of the deck, e.g. 'variable broken equal $(c_frac[3])'")


def failed(c, left, since, partitions, output):
    """[(case, message)] of the cases that failed among `left` (not done),
    [] if none had started, or None when the culprit is ambiguous (several
    partitions, cases started, no ERROR reached a log)."""
    running = started(c, left, since)
    found = []
    for case in running:
        m = results.missing_path(c, case)
        log = os.path.relpath(log_path(c, case))
        if os.path.isfile(m):
            found.append((case, f"{missing_message(c, open(m).read().split())}  (log: {log})"))
            continue
        e = error_of(log_path(c, case))
        if e is None and partitions == 1 and len(running) == 1:
            e = error_of(output) or "lmp stopped with no ERROR line (see the output)"
            log += f", output: {os.path.relpath(output)}"
        if e:
            found.append((case, f"{e}  (log: {log})"))
    if found or partitions == 1 or not running:
        return found
    return None
