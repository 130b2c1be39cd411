"""Starting lmp: the command line, the folder lock, the wait.

lmp runs in the campaign file's folder (decks see their paths as when run
by hand there). LAMMPS's uloop counter, tmp.lammps.variable, lives in that
folder, so one campaign at a time runs there: the driver holds a lock on
.pd_campaign.lock and hands it to lmp, which keeps it while it runs even
if the driver is killed."""
import fcntl
import os
import shutil
import signal
import subprocess
import time

ULOOP_FILES = ("tmp.lammps.variable", "tmp.lammps.variable.lock")


class Interrupted(Exception):
    pass


def lock(home):
    """An exclusive lock on the folder; returns its file descriptor."""
    fd = os.open(os.path.join(home, ".pd_campaign.lock"), os.O_RDWR | os.O_CREAT, 0o644)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        raise RuntimeError(f"another campaign (or its lmp) is running in {home}: "
                           "LAMMPS's uloop counter (tmp.lammps.variable) allows one per folder")
    return fd


def command(lmp, deck, log, partitions=1, ranks=1, mpirun="mpirun", plog=None):
    """lmp's command line: mpirun only when more than one rank runs. On one
    partition the screen is line-buffered (stdbuf), so that an ERROR
    reaches the output file even when LAMMPS ends by MPI_Abort, which
    flushes nothing."""
    cmd = [lmp, "-in", deck, "-log", log]
    if partitions == 1 and shutil.which("stdbuf"):
        cmd = ["stdbuf", "-oL"] + cmd
    if partitions > 1:
        cmd += ["-partition", f"{partitions}x{ranks}", "-plog", plog or log, "-pscreen", "none"]
    n = partitions * ranks
    return (mpirun.split() + ["-np", str(n)] + cmd) if n > 1 else cmd


def clear_uloop(home):
    """A counter left by an interrupted run would hand out wrong indices."""
    for f in ULOOP_FILES:
        try:
            os.remove(os.path.join(home, f))
        except FileNotFoundError:
            pass


def run(cmd, cwd, output, lock_fd, poll=None, every=0.5):
    """Run cmd (its output to the file output), calling poll() every
    `every` seconds; returns the exit status. SIGINT or SIGTERM stop lmp
    (its whole process group) and raise Interrupted."""
    def stop(signum, frame):
        raise Interrupted(signal.Signals(signum).name)
    old = {s: signal.signal(s, stop) for s in (signal.SIGINT, signal.SIGTERM)}
    with open(output, "w") as out:
        # lmp leads a process group of its own, which kill() signals whole
        # (this runner has no threads: preexec_fn is safe here)
        p = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT,
                             stdin=subprocess.DEVNULL, preexec_fn=os.setpgrp, pass_fds=(lock_fd,))
        try:
            while p.poll() is None:
                time.sleep(every)
                if poll:
                    poll()
            return p.returncode
        finally:
            if p.poll() is None:
                kill(p)
            for s, h in old.items():
                signal.signal(s, h)


def kill(p):
    for sig, wait in ((signal.SIGTERM, 5), (signal.SIGKILL, 5)):
        try:
            os.killpg(p.pid, sig)
        except ProcessLookupError:
            return
        try:
            p.wait(wait)
            return
        except subprocess.TimeoutExpired:
            pass
