"""The campaign file: which decks, which cases, which results.

An INI file (doc/campaign.md):

  [campaign]
  case    = in.case          the case deck (required)
  prepare = in.prepare       run once, writes the restart (optional)
  restart = target.restart   the target (default <out>/target.restart with prepare)
  results = broken tip       variables the case deck leaves defined (required)
  cases   = cases.csv        the case list, or a [grid] section
  out     = DIR              results, logs, generated decks (default <name>.out)
  plot    = v0 broken tip    x column, then y columns (optional, gnuplot)

  [variables]                one value each: given to the prepare deck and every case
  [grid]                     values of each case variable: every combination
  [labels]                   axis labels of the plot's columns, with units

Paths are relative to the campaign file's folder, where lmp runs."""
import configparser
import csv
import hashlib
import itertools
import os
import re

NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*$")
BAD_VALUE = re.compile(r"[\s\"'#$,]")     # LAMMPS takes a variable's value as one word
BAD_PATH = re.compile(r"[\s\"'#$]")
SAFE = re.compile(r"[^A-Za-z0-9._+-]")
KEYS = {"case", "prepare", "restart", "results", "cases", "out", "plot"}
SECTIONS = {"campaign", "variables", "grid", "labels"}
RESERVED = ("restart", "campaign_")       # names the runner defines


class CampaignError(Exception):
    """A mistake in the campaign's input, said so that the user can fix it."""


class Campaign:
    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.home = os.path.dirname(self.path)
        self.name = os.path.splitext(os.path.basename(self.path))[0]
        self.prepare = self.restart = None
        self.variables, self.names, self.cases, self.plot, self.labels = {}, [], [], None, {}

    def file(self, rel, what, must_exist=True):
        """A path named in the campaign file, absolute."""
        p = os.path.normpath(os.path.join(self.home, rel))
        if must_exist and not os.path.isfile(p):
            raise CampaignError(f"{self.where()}: {what} '{rel}' does not exist ({p})")
        return p

    def where(self):
        return os.path.basename(self.path)

    def rel(self, p):
        """p as lmp (running in home) should see it: one word, no spaces."""
        r = os.path.relpath(p, self.home)
        if BAD_PATH.search(r):
            raise CampaignError(f"path '{r}' has a space, quote, '#' or '$': LAMMPS reads it as "
                                "several words or a comment; move the campaign to a plain path")
        return r


def key(case):
    """The name of a case: its files are results/<key>.txt and logs/<key>.log."""
    raw = ",".join(f"{n}={v}" for n, v in case.items())
    k = ",".join(f"{n}={SAFE.sub('_', v)}" for n, v in case.items())
    if k != raw or len(k) > 120:
        k = k[:100] + "-" + hashlib.sha1(raw.encode()).hexdigest()[:8]
    return k


def check_name(name, where):
    if not NAME.match(name):
        raise CampaignError(f"{where}: '{name}' is not a LAMMPS variable name (letters, digits, _)")
    if name == RESERVED[0] or name.startswith(RESERVED[1]):
        raise CampaignError(f"{where}: the name '{name}' is the runner's own (restart, campaign_*)")


def check_value(name, value, where):
    if value == "":
        raise CampaignError(f"{where}: variable '{name}' has no value")
    if BAD_VALUE.search(value):
        raise CampaignError(f"{where}: value '{value}' of '{name}' has a space, quote, comma, '#' or '$' "
                            "(a LAMMPS variable's value is one word)")


def read_grid(c, section):
    names, lists = [], []
    for name, text in section.items():
        where = f"{c.where()} [grid] {name}"
        check_name(name, where)
        values = text.split()
        if not values:
            raise CampaignError(f"{where}: no values")
        for v in values:
            check_value(name, v, where)
        if len(set(values)) != len(values):
            raise CampaignError(f"{where}: a value is listed twice")
        names.append(name)
        lists.append(values)
    return names, [dict(zip(names, combo)) for combo in itertools.product(*lists)]


def read_table(c, path):
    """A CSV case list: a header of variable names, then one case a line;
    blank lines and lines starting with # are skipped."""
    rows, names = [], None
    with open(path, newline="") as f:
        for lineno, fields in enumerate(csv.reader(f), 1):
            where = f"{os.path.basename(path)} line {lineno}"
            fields = [x.strip() for x in fields]
            if not fields or fields == [""] or fields[0].startswith("#"):
                continue
            if names is None:
                for n in fields:
                    check_name(n, where)
                if len(set(fields)) != len(fields):
                    raise CampaignError(f"{where}: a variable is named twice in the header")
                names = fields
                continue
            if len(fields) != len(names):
                raise CampaignError(f"{where}: {len(fields)} values for {len(names)} variables "
                                    f"({', '.join(names)})")
            for n, v in zip(names, fields):
                check_value(n, v, where)
            rows.append((lineno, dict(zip(names, fields))))
    if names is None:
        raise CampaignError(f"{os.path.basename(path)}: no header line naming the case variables")
    seen = {}
    for lineno, case in rows:
        k = tuple(case.values())
        if k in seen:
            raise CampaignError(f"{os.path.basename(path)} line {lineno}: the same case as line {seen[k]}")
        seen[k] = lineno
    return names, [case for _, case in rows]


def load(path):
    """Read and check a campaign file; CampaignError names what is wrong."""
    c = Campaign(path)
    if not os.path.isfile(c.path):
        raise CampaignError(f"campaign file '{path}' does not exist")
    ini = configparser.ConfigParser(interpolation=None, inline_comment_prefixes=("#", ";"))
    ini.optionxform = str                       # LAMMPS names are case-sensitive
    try:
        ini.read(c.path)
    except configparser.Error as e:
        raise CampaignError(f"{c.where()}: {e}".replace("\n", " "))
    unknown = set(ini.sections()) - SECTIONS
    if unknown:
        raise CampaignError(f"{c.where()}: unknown section [{sorted(unknown)[0]}] "
                            f"(known: {', '.join(sorted(SECTIONS))})")
    if "campaign" not in ini:
        raise CampaignError(f"{c.where()}: no [campaign] section")
    s = ini["campaign"]
    unknown = set(s) - KEYS
    if unknown:
        raise CampaignError(f"{c.where()}: unknown key '{sorted(unknown)[0]}' in [campaign] "
                            f"(known: {', '.join(sorted(KEYS))})")
    if "case" not in s:
        raise CampaignError(f"{c.where()}: [campaign] names no case deck (case = in.case)")
    c.case = c.file(s["case"], "case deck")
    c.out = c.file(s.get("out", c.name + ".out"), "out", must_exist=False)
    if "prepare" in s:
        c.prepare = c.file(s["prepare"], "prepare deck")
    if "restart" in s:
        c.restart = c.file(s["restart"], "restart", must_exist=False)
    elif c.prepare:
        c.restart = os.path.join(c.out, "target.restart")

    c.results = s.get("results", "").split()
    if not c.results:
        raise CampaignError(f"{c.where()}: [campaign] names no results (results = var1 var2 ...: "
                            "variables the case deck leaves defined)")
    for r in c.results:
        check_name(r, f"{c.where()} results")

    for name, value in (ini["variables"].items() if "variables" in ini else []):
        check_name(name, f"{c.where()} [variables]")
        check_value(name, value.strip(), f"{c.where()} [variables]")
        c.variables[name] = value.strip()

    if ("cases" in s) == ("grid" in ini):
        raise CampaignError(f"{c.where()}: give the cases either as 'cases = file.csv' in [campaign] "
                            "or as a [grid] section (one of the two)")
    if "cases" in s:
        c.names, c.cases = read_table(c, c.file(s["cases"], "case list"))
    else:
        c.names, c.cases = read_grid(c, ini["grid"])
    if not c.cases:
        raise CampaignError(f"{c.where()}: the case list is empty")

    for n in c.names:
        if n in c.variables:
            raise CampaignError(f"{c.where()}: '{n}' is both a case variable and in [variables]")
        if n in c.results:
            raise CampaignError(f"{c.where()}: '{n}' is both a case variable and a result")
    for r in c.results:
        if r in c.variables:
            raise CampaignError(f"{c.where()}: '{r}' is both a result and in [variables]")
    keys = {}
    for case in c.cases:
        k = key(case)
        if k in keys:
            raise CampaignError(f"{c.where()}: cases {keys[k]} and {case} get the same file name {k}")
        keys[k] = case

    if "plot" in s:
        cols = s["plot"].split()
        known = c.names + c.results
        if len(cols) < 2 or any(x not in known for x in cols):
            raise CampaignError(f"{c.where()}: plot = x y [y ...] with columns of the results "
                                f"({', '.join(known)}); got '{s['plot']}'")
        c.plot = cols
    for col, text in (ini["labels"].items() if "labels" in ini else []):
        if col not in c.names + c.results:
            raise CampaignError(f"{c.where()} [labels]: '{col}' is not a column of the results "
                                f"({', '.join(c.names + c.results)})")
        c.labels[col] = text.strip()
    for p in (c.case, c.prepare, c.restart, c.out):
        if p:
            c.rel(p)
    return c
