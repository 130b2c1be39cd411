"""Each case's result file and the campaign's CSV.

The loop deck writes results/<key>.txt when its case ends: one line
'name value' per case variable and result, then '# complete'. A case is
done when its file ends with that line, names the case's own values and
every result, and is not older than the target restart; any other file
(half written, damaged, from an older target) does not count, and that
case runs again."""
import csv
import os

from campaign_file import key

COMPLETE = "# complete"


def path(c, case):
    return os.path.join(c.out, "results", key(case) + ".txt")


def missing_path(c, case):
    """Written by the loop deck when the case deck leaves a result undefined."""
    return os.path.join(c.out, "results", key(case) + ".missing")


def read(c, case, not_before=0.0):
    """{column: value} of a finished case, or None if the case is not done."""
    p = path(c, case)
    try:
        if os.path.getmtime(p) < not_before:
            return None
        lines = open(p).read().splitlines()
    except OSError:
        return None
    if not lines or lines[-1].strip() != COMPLETE:
        return None
    values = {}
    for line in lines:
        if line.startswith("#"):
            continue
        w = line.split(None, 1)
        if len(w) == 2:
            values[w[0]] = w[1].strip()
    if any(values.get(n) != v for n, v in case.items()):
        return None
    if any(r not in values for r in c.results):
        return None
    return {n: values[n] for n in c.names + c.results}


def scan(c, not_before=0.0):
    """{key: row} of every finished case of the list."""
    done = {}
    for case in c.cases:
        row = read(c, case, not_before)
        if row is not None:
            done[key(case)] = row
    return done


def write_csv(c, done):
    """The campaign's CSV: a header, then the finished cases in list order.
    Written to a temporary file and renamed, so a reader never sees half."""
    out = csv_path(c)
    tmp = out + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(c.names + c.results)
        for case in c.cases:
            row = done.get(key(case))
            if row:
                w.writerow([row[n] for n in c.names + c.results])
    os.replace(tmp, out)
    return out


def csv_path(c):
    return os.path.join(c.out, "results.csv")
