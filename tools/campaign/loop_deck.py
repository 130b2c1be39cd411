"""The generated LAMMPS input that runs the pending cases.

loop.lmp counts through the pending cases with a uloop variable (a loop
variable on one partition): each partition takes the next case nobody
has taken, includes deck/case.<i>.lmp (its log, clear, its variables),
then the user's case deck, then writes the case's result file. One lmp
run does every pending case; LAMMPS hands them to free partitions."""
import os
import re

import results
from campaign_file import key

DEFINED = re.compile(r"^\s*variable\s+([A-Za-z_][A-Za-z0-9_]*)\s+(\S+)", re.M)


def deck_variables(c):
    """Variables the case deck defines: deleted before each case, so that a
    case does not see what the previous case on its partition left."""
    names = []
    for name, style in DEFINED.findall(open(c.case).read()):
        if style != "delete" and not name.startswith("campaign_") and name not in names:
            names.append(name)
    return names


def set_variable(name, value):
    return f"variable {name} delete\nvariable {name} index {value}\n"


def case_file(c, case, stale):
    k = key(case)
    text = (f"# {k}\nlog {c.rel(os.path.join(c.out, 'logs', k + '.log'))}\nclear\n"
            + "".join(f"variable {n} delete\n" for n in stale)
            + f"variable campaign_case string {k}\n")
    if c.restart:
        text += set_variable("restart", c.rel(c.restart))
    for n, v in list(c.variables.items()) + list(case.items()):
        text += set_variable(n, v)
    return text + f'print "CAMPAIGN-CASE-START {k}"\n'


def loop_file(c, count, partitions):
    res = c.rel(os.path.join(c.out, "results")) + "/${campaign_case}.txt"
    style = "uloop" if partitions > 1 else "loop"
    lines = [f"# Written by tools/campaign/pd_campaign.py for {c.where()} at each launch: do not edit.",
             f"# {count} pending cases; each partition takes the next one nobody has taken ({style}).",
             f"variable campaign_i {style} {count}",
             "label campaign_next",
             f"include {c.rel(os.path.join(c.out, 'deck'))}/case.${{campaign_i}}.lmp",
             f"include {c.rel(c.case)}",
             "# the results convention: the case deck leaves these variables defined;",
             "# a missing one is noted in <case>.missing (on disk before the ERROR that follows)"]
    missing = c.rel(os.path.join(c.out, "results")) + "/${campaign_case}.missing"
    for r in c.results:
        lines.append(f'if "$(is_defined(variable,{r})) == 0" then '
                     f'"print {r} append {missing} screen no"')
    # written in place by the world's first rank; the last line marks it whole
    lines.append(f'print "# ${{campaign_case}}" file {res} screen no')
    for n in c.names + c.results:
        lines.append(f'print "{n} ${{{n}}}" append {res} screen no')
    lines += [f'print "# complete" append {res} screen no',
              f'print "CAMPAIGN-CASE-DONE ${{campaign_case}}"',
              "next campaign_i",
              "jump SELF campaign_next"]
    return "\n".join(lines) + "\n"


def write(c, pending, partitions):
    """Write deck/loop.lmp and deck/case.<i>.lmp for the pending cases;
    returns the loop deck's path."""
    d = os.path.join(c.out, "deck")
    os.makedirs(d, exist_ok=True)
    for f in os.listdir(d):
        os.remove(os.path.join(d, f))
    own = set(c.names) | set(c.variables) | {"restart"}
    stale = [n for n in dict.fromkeys(deck_variables(c) + c.results) if n not in own]
    for i, case in enumerate(pending, 1):
        if os.path.exists(results.missing_path(c, case)):
            os.remove(results.missing_path(c, case))
        with open(os.path.join(d, f"case.{i}.lmp"), "w") as f:
            f.write(case_file(c, case, stale))
    loop = os.path.join(d, "loop.lmp")
    with open(loop, "w") as f:
        f.write(loop_file(c, len(pending), partitions))
    return loop
