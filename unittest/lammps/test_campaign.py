"""The campaign runner (tools/campaign/pd_campaign.py): every case runs
once, a campaign resumes without running a finished case again, and the
results do not depend on interruptions or on the number of partitions.

It runs examples/campaign-basics at a coarse spacing (h = 0.5 mm, 1891
particles, 8 cases of about 0.3 s). A copy of the case deck counts its
starts (starts.txt) and fails on purpose for the case whose v is the
environment variable PDTEST_FAIL_V. The reference is an uninterrupted run
on one partition; every other run must give its CSV: the same rows, and
values equal to 1e-12 relative (each case is the same deck on one rank of
the same binary from the same restart, so the same floating-point
operations; 1e-12 allows only the last digits of LAMMPS's %.15g)."""
import csv
import os
import shutil
import signal
import subprocess
import sys
import time
from lmptest import *

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "../../examples/campaign-basics")
DRIVER = os.path.join(HERE, "../../tools/campaign/pd_campaign.py")
CASES = ["0.5", "1", "1.5", "2", "3", "4", "6", "8"]
HOOK = """read_restart    ${restart}
print           "${v}" append starts.txt screen no
variable        failv getenv PDTEST_FAIL_V
if              "${failv} == ${v}" then "fix deliberate all no-such-fix-style"
"""


def campaign(tag, ini_edits=(), case_edits=()):
    """A copy of the example at h = 0.5 mm, with the counting hook."""
    d = os.path.join(workdir(), tag)
    shutil.copytree(EXAMPLE, d, ignore=shutil.ignore_patterns("*.out", "*.restart", "log.*", "tmp.lammps.*",
                                                            ".pd_campaign.lock", "starts.txt"))
    ini = replace_exact(open(f"{d}/campaign.ini").read(), "h = 2.5e-4", "h = 5e-4")
    case = replace_exact(open(f"{d}/in.case").read(), "read_restart    ${restart}\n", HOOK)
    for old, new in ini_edits:
        ini = replace_exact(ini, old, new)
    for old, new in case_edits:
        case = replace_exact(case, old, new)
    open(f"{d}/campaign.ini", "w").write(ini)
    open(f"{d}/in.case", "w").write(case)
    return d


def drive(d, *args, fail=None, background=False):
    env = dict(MPI_ENV)
    env["PDTEST_FAIL_V"] = fail or "-1"        # the grip speed of the case that fails
    cmd = [sys.executable, DRIVER, "campaign.ini", "--lmp", LMP] + list(args)
    if background:
        return subprocess.Popen(cmd, cwd=d, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    p = subprocess.run(cmd, cwd=d, env=env, capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout + p.stderr


def starts(d):
    """{v: number of times the case deck started for v}"""
    n = {}
    if os.path.isfile(f"{d}/starts.txt"):
        for line in open(f"{d}/starts.txt").read().split():
            n[line] = n.get(line, 0) + 1
    return n


def table(d):
    with open(f"{d}/campaign.out/results.csv") as f:
        return list(csv.reader(f))


def same_table(what, d, ref):
    """Same header, same case column, results equal to 1e-12 relative."""
    got = table(d)
    if len(got) != len(ref) or got[0] != ref[0] or [r[0] for r in got] != [r[0] for r in ref]:
        check(f"{what}: the CSV has the reference's rows", False, f"{[r[0] for r in got]}")
        return
    worst = max(abs(float(a) - float(b)) / max(abs(float(b)), 1e-300)
                for g, r in zip(got[1:], ref[1:]) for a, b in zip(g[1:], r[1:]))
    check_le(f"{what}: CSV equals the uninterrupted one ({len(got) - 1} rows)", worst, 1e-12,
             "same operations on one rank; %.15g round-off")


def done_cases(d):
    r = f"{d}/campaign.out/results"
    return sorted(f[2:-4] for f in os.listdir(r) if f.endswith(".txt")) if os.path.isdir(r) else []


t0 = time.time()
# -- reference: one partition, uninterrupted
ref_dir = campaign("ref")
rc, out = drive(ref_dir)
ref = table(ref_dir)
check("reference run ends with every case done", rc == 0 and len(ref) == 1 + len(CASES), out[-300:])
check("reference: every case started once", starts(ref_dir) == {v: 1 for v in CASES}, f"{starts(ref_dir)}")
check("reference: the cases differ (some bonds break, some not)",
      ref[1][1] == "0" and float(ref[-1][1]) > 1000, f"broken {ref[1][1]} .. {ref[-1][1]}")
check("progress lines count cases, time elapsed and left",
      "[8/8] v=8" in out and "elapsed" in out and "left ~" in out)

# -- a case fails; the rerun resumes
d = campaign("fail")
rc, out = drive(d, fail="2")
check("a failing case stops the campaign (exit 1) and is named with its ERROR",
      rc == 1 and "case v=2 FAILED" in out and "no-such-fix-style" in out, out[-400:])
check("cases before the failure are done (one partition: in order)", done_cases(d) == ["0.5", "1", "1.5"],
      f"{done_cases(d)}")
rc, out = drive(d)
n = starts(d)
check("resumed: the finished cases did not run again, the failed one ran again",
      rc == 0 and n == dict({v: 1 for v in CASES}, **{"2": 2}), f"{n}")
check("resumed: the resume says which cases it kept", "3/8 cases done earlier" in out, out[:300])
same_table("after a failure and a resume", d, ref)

# -- the driver is stopped; a result file is damaged by hand; the rerun resumes
d = campaign("kill")
p = drive(d, background=True)
while len(done_cases(d)) < 2 and p.poll() is None:
    time.sleep(0.05)
p.send_signal(signal.SIGTERM)
out = p.communicate(timeout=60)[0]
before, n_before = done_cases(d), starts(d)
check("SIGTERM stops the driver (exit 130) and says how to resume",
      p.returncode == 130 and "run the same command again" in out, out[-300:])
time.sleep(1.0)
check("SIGTERM stops lmp too (no case starts or ends afterwards)",
      done_cases(d) == before and starts(d) == n_before, f"{before}")
check("the driver stopped with cases still to do", 2 <= len(before) < len(CASES), f"{before}")
rc, status = drive(d, "--status")
check("--status counts the finished cases", f"{len(before)}/8 cases done" in status, status[:200])
damaged = before[0]
path = f"{d}/campaign.out/results/v={damaged}.txt"
text = replace_exact(open(path).read(), "# complete\n", "")      # as if cut short
open(path, "w").write(text)
rc, out = drive(d)
n = starts(d)
expected = {v: n_before.get(v, 0) + (0 if v in before and v != damaged else 1) for v in CASES}
check("resumed after SIGTERM: finished cases did not run again, the damaged one did",
      rc == 0 and n == expected and n[damaged] == 2, f"{n}, expected {expected}")
check("the damaged result file was reported", "incomplete or older than the target restart" in out)
same_table("after SIGTERM, a damaged result and a resume", d, ref)

# -- two partitions
d = campaign("p2")
rc, out = drive(d, "-p", "2")
check("2 partitions: mpirun -np 2 ... -partition 2x1", "-partition 2x1" in out and rc == 0, out[-300:])
check("2 partitions: every case started exactly once", starts(d) == {v: 1 for v in CASES}, f"{starts(d)}")
logs = open(f"{d}/campaign.out/lmp.out").read()
check("2 partitions: both partitions took cases (uloop)",
      "on partition 0" in logs and "on partition 1" in logs, logs[-300:])
same_table("2 partitions", d, ref)

# -- two partitions, a failing case, --keep-going: only that case is blamed
d = campaign("p2fail")
rc, out = drive(d, "-p", "2", "--keep-going", fail="1.5")
check("2 partitions, --keep-going: one case failed and is named", rc == 1 and out.count("FAILED") == 1
      and "case v=1.5 FAILED" in out, out[-400:])
check("2 partitions, --keep-going: every other case is done",
      sorted(done_cases(d)) == sorted(v for v in CASES if v != "1.5"), f"{done_cases(d)}")
rc, out = drive(d, "-p", "2")
check("rerun: only the failed case runs", rc == 0 and "running 1 on 1 partition" in out, out[-300:])
same_table("2 partitions with a failure, then rerun", d, ref)

# -- input validation: each mistake gets a message that names it
one_case = [("v = 0.5 1 1.5 2 3 4 6 8", "v = 1")]
d = campaign("missing", ini_edits=one_case,       # the deck names its result vfast, not vmax
             case_edits=[("variable        vmax equal", "variable        vfast equal"),
                         ("vmax ${vmax} m/s", "vmax ${vfast} m/s")])
rc, out = drive(d)
check("a case deck without a result variable: named, with the convention",
      rc == 1 and "leaves no variable vmax defined" in out and "results" in out, out[-400:])

d = campaign("norestart", ini_edits=[("prepare = in.prepare ", "restart = nothere.restart ")])
rc, out = drive(d)
check("a missing restart without a prepare deck: named",
      rc == 2 and "restart nothere.restart does not exist and no prepare deck makes it" in out, out[-300:])

d = campaign("nowrite", ini_edits=one_case)
prep = replace_exact(open(f"{d}/in.prepare").read(), "write_restart   ${restart}\n", "")
open(f"{d}/in.prepare", "w").write(prep)
rc, out = drive(d)
check("a prepare deck that writes no restart: said, with the fix",
      rc == 2 and "wrote no restart" in out and "write_restart ${restart}" in out, out[-300:])

d = campaign("badprep", ini_edits=one_case)
open(f"{d}/in.prepare", "a").write("fix oops all no-such-style\n")
rc, out = drive(d, "--prepare")
check("a prepare deck with an ERROR: its ERROR line is shown",
      rc == 2 and "prepare deck in.prepare failed" in out and "no-such-style" in out, out[-300:])

BAD = {
    "a row with too many values": ("v\n1\n2,3\n", "cases.csv line 3: 2 values for 1 variables (v)"),
    "a value with a space": ("v\n1 2\n", "cases.csv line 2: value '1 2' of 'v' has a space"),
    "a header that is no variable name": ("2v\n1\n", "cases.csv line 1: '2v' is not a LAMMPS variable name"),
    "the same case twice": ("v\n1\n# comment\n1\n", "cases.csv line 4: the same case as line 2"),
    "no cases": ("v\n", "the case list is empty"),
    "a reserved name": ("restart\n1\n", "'restart' is the runner's own"),
}
for what, (text, message) in BAD.items():
    d = campaign("badcases", ini_edits=[("[grid]\nv = 0.5 1 1.5 2 3 4 6 8", ""),
                                        ("prepare = in.prepare ", "cases = cases.csv\nprepare = in.prepare ")])
    open(f"{d}/cases.csv", "w").write(text)
    rc, out = drive(d)
    check(f"bad case file, {what}: exit 2, message names it", rc == 2 and message in out, out.strip()[-200:])
for what, edit, message in [
        ("an unknown key", ("case    = in.case", "case    = in.case\ncase_deck = x"), "unknown key 'case_deck'"),
        ("grid and case file both", ("prepare = in.prepare ", "cases = x.csv\nprepare = in.prepare "),
         "either as 'cases = file.csv'"),
        ("a missing case deck", ("case    = in.case", "case    = in.nothere"), "case deck 'in.nothere' does not exist"),
        ("no results", ("results = broken energy crack vmax", "results ="), "names no results")]:
    d = campaign("badini", ini_edits=[edit])
    rc, out = drive(d)
    check(f"bad campaign file, {what}: exit 2, message names it", rc == 2 and message in out, out.strip()[-200:])
print(f"test time {time.time() - t0:.1f} s")
finish()
