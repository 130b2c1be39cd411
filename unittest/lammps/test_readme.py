"""README's minimal deck runs as printed: the first code block under
"A minimal deck", fed to lmp unchanged, breaks bonds (a crack grows from
the notch: more than 1000 bonds, 2385 measured) and books their energy
(more than 10 mJ, 24.5 mJ measured), with no WARNING or ERROR; and its
dump draws with tools/pd_picture.py. The deck runs with the neighbor
defaults of the LAMMPS under test, as a user's would."""
import os
import subprocess
import sys
from lmptest import *

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "../..")
text = open(os.path.join(ROOT, "README.md")).read()
section = text[text.index("## A minimal deck"):]
deck = section.split("```\n", 2)[1]
check("the README has the deck (pair_style and run)", "pair_style" in deck and "\nrun " in deck)
d = workdir()
out, rows = run(deck, d, as_is=True)    # with the defaults of the LAMMPS it runs on
check("it breaks bonds: a crack grows from the notch", rows and rows[-1]["c_frac[3]"] > 1000,
      f"{rows[-1]['c_frac[3]']:.0f} bonds" if rows else "no thermo")
check("... and books their energy (J)", rows and rows[-1]["c_frac[2]"] > 0.01, f"{rows[-1]['c_frac[2]']:.4g} J" if rows else "")
check("no WARNING or ERROR", "WARNING" not in out and "ERROR" not in out,
      next((l for l in out.splitlines() if "WARNING" in l or "ERROR" in l), ""))
p = subprocess.run([sys.executable, os.path.join(ROOT, "tools/pd_picture.py"), os.path.join(d, "dump.crack"),
                    os.path.join(d, "crack.png"), "--color", "c_dmg", "--range", "0", "0.6", "--label", "damage"],
                   capture_output=True, text=True)
check("its dump draws (tools/pd_picture.py)", p.returncode == 0 and os.path.getsize(os.path.join(d, "crack.png")) > 10000,
      (p.stdout + p.stderr).strip()[:200])
finish()
