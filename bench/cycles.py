#!/usr/bin/env python3
"""Per-step cost of bench/in.block styles, counted rather than timed.

    python3 bench/cycles.py LMP STYLE [STYLE ...]

For a machine too noisy to time on (bench/README.md). Each style runs twice
under valgrind's callgrind, for 10 and for 30 steps; the difference over 20
steps leaves out the setup (family build, first evaluation). Two numbers per
step:
- instructions (callgrind's count; valgrind counts every byte that a
  'rep stos'/'rep movs' of memset and memcpy writes as one);
- modeled cycles: in LMP's own code, each loop body (the instructions of one
  function that ran the same number of times, at least 20000) costs its
  count times llvm-mca's steady-state cycles per iteration on Zen 3; every
  other instruction one cycle, memset and memcpy 32 bytes per cycle. A
  model of a core without cache misses or mispredicted branches, fit for
  the compute-bound bond loops.
Ratios are to the first style. Needs valgrind and llvm-mca (Debian: llvm).
"""
import collections
import functools
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
LOOP_MIN = 20000


def profile(lmp, style, steps, out):
    subprocess.run(["valgrind", "--tool=callgrind", "--dump-instr=yes", f"--callgrind-out-file={out}",
                    lmp, "-in", "in.block", "-var", "style", style, "-var", "steps", str(steps),
                    "-log", "none", "-screen", "none"], cwd=HERE, check=True, capture_output=True)


def counts(path):
    """{(object, function): {address: instructions}} of a --dump-instr profile."""
    per = collections.defaultdict(collections.Counter)
    names, objs, cur, obj, last, call = {}, {}, None, None, 0, False
    for line in open(path):
        m = re.match(r"(c?)(ob|fn)=\((\d+)\)(?: (.*))?", line)
        if m:
            table = objs if m.group(2) == "ob" else names
            if m.group(4): table[m.group(3)] = m.group(4).strip()
            if not m.group(1):
                if m.group(2) == "ob": obj = table.get(m.group(3))
                else: cur = (obj, table.get(m.group(3)))
            continue
        if line.startswith("calls="):
            call = True
            continue
        m = re.match(r"^(0x[0-9a-f]+|[+-]\d+|\*)\s+(?:\S+\s+)?(\d+)$", line)
        if m:
            a = m.group(1)
            last = int(a, 16) if a.startswith("0x") else last if a == "*" else last + int(a)
            if not call and cur: per[cur][last] += int(m.group(2))
            call = False
    return per


@functools.lru_cache(None)
def mca_cycles(body):
    out = subprocess.run(["llvm-mca", "-mcpu=znver3", "-iterations=400"], input=body,
                         capture_output=True, text=True, check=True).stdout
    return (int(re.search(r"Total Cycles:\s+(\d+)", out).group(1))
            / int(re.search(r"Iterations:\s+(\d+)", out).group(1)))


def modeled(lmp, per):
    total = 0.0
    for (obj, fn), cnt in per.items():
        n = sum(cnt.values())
        if fn and re.search(r"mem(set|cpy|move)", fn):
            total += n / 32
            continue
        if not obj or os.path.basename(obj) != os.path.basename(lmp) or n < 1000000:
            total += n
            continue
        dis = subprocess.run(["objdump", "-d", "--no-show-raw-insn", f"--start-address={min(cnt)}",
                              f"--stop-address={max(cnt) + 16}", lmp], capture_output=True, text=True).stdout
        text = {int(m.group(1), 16): re.sub(r"\s*#.*$", "", m.group(2)).strip()
                for m in re.finditer(r"^\s*([0-9a-f]+):\s*(.*)$", dis, re.M)}
        loops = collections.defaultdict(list)
        for a in sorted(cnt):
            if cnt[a] >= LOOP_MIN and a in text:
                # (the back branch and calls are not part of the body mca models)
                if not re.match(r"(j\w+|call|ret|nop)", text[a]): loops[cnt[a]].append(text[a])
            else:
                total += cnt[a]
        total += sum(c * mca_cycles("\n".join(body) + "\n") for c, body in loops.items() if body)
    return total


def main():
    if len(sys.argv) < 3: sys.exit(__doc__)
    lmp, styles = os.path.abspath(sys.argv[1]), sys.argv[2:]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for style in styles:
            ins, cyc = [], []
            for steps in (10, 30):
                out = os.path.join(tmp, f"cg.{style}.{steps}")
                profile(lmp, style, steps, out)
                per = counts(out)
                ins.append(sum(sum(c.values()) for c in per.values()))
                cyc.append(modeled(lmp, per))
            rows.append((style, (ins[1] - ins[0]) / 20, (cyc[1] - cyc[0]) / 20))
    print(f"{'style':28s} {'instructions/step':>18s} {'ratio':>6s} {'modeled cycles/step':>20s} {'ratio':>6s}")
    for style, i, c in rows:
        print(f"{style:28s} {i / 1e6:16.3f} M {i / rows[0][1]:6.3f} {c / 1e6:18.3f} M {c / rows[0][2]:6.3f}")


if __name__ == "__main__":
    main()
