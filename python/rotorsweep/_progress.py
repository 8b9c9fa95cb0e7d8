"""The progress line of rotorsweep.run on sys.stderr: members done / total, rate, time left and the
periods the members have closed (so that it moves while a few long members run); redrawn in place on a
terminal, one line every 10 s otherwise (like the command line's); its last line, or the line that says
where a stopped run keeps its members."""

import sys
import time


def write(text, flush=False):
    """text on sys.stderr; nothing where there is none (sys.stderr None, as under pythonw). A stream that
    raises raises here: the caller's job is stopped before the error goes on."""
    stream = sys.stderr
    if stream is None:
        return
    stream.write(text)
    if flush:
        stream.flush()


class ProgressLine:
    def __init__(self, total, enabled):
        self.total = total
        self.enabled = enabled
        self.terminal = enabled and sys.stderr is not None and sys.stderr.isatty()
        self.start = self.last = time.monotonic()
        self.width = 0

    def update(self, done, periods=0):
        if not self.enabled:
            return
        now = time.monotonic()
        if now - self.last < (0.25 if self.terminal else 10.0):
            return
        self.last = now
        elapsed = now - self.start
        rate = done / elapsed if elapsed > 0 else 0.0
        left = f", {(self.total - done) / rate:.0f} s left" if rate > 0 else ""
        text = f"{done}/{self.total} members ({100 * done / max(self.total, 1):.1f} %, {rate:.1f}/s{left})"
        if periods > 0:
            text += f"  ({periods} periods closed)"
        if self.terminal:
            write("\r" + text.ljust(self.width), flush=True)
            self.width = len(text)
        else:
            write(text + "\n", flush=True)

    def finish(self):
        if self.terminal and self.width:
            write("\r" + " " * self.width + "\r", flush=True)


def report(h5file, path):
    """The last lines `rotorsweep run` prints, from a finished result: members, time, rate and lane
    occupancy, then the members that did not finish, and, each reason apart, those whose D is not
    resolved, is symmetry-limited or whose shadow departed."""
    attrs, members = h5file.attrs, h5file["members"]
    count = members["status"].shape[0]
    seconds = float(attrs["wall_seconds"])
    where = f"wrote {path}" if path else "rotorsweep.run"
    rate = f"{count / seconds:.1f} members/s" if seconds > 0 else "instant"
    write(f"{where}: {count} members in {seconds:.3g} s ({rate}, lane occupancy "
                     f"{100 * float(attrs['lane_occupancy']):.1f} %)\n")
    status = [s.decode() if isinstance(s, bytes) else str(s) for s in members["status"][:]]
    ok = [s == "ok" for s in status]
    failed = {}
    for s in status:
        if s != "ok":
            failed[s] = failed.get(s, 0) + 1
    if failed:
        listed = " ".join(f"{name} {n}" for name, n in sorted(failed.items()))
        write(f"warning: members that did not finish (their observables are NaN): {listed}\n")
    flag = {name: members[name][:] != 0 if name in members else [False] * count
            for name in ("symmetry_limited", "symmetry_held", "shadow_departed")}
    resolved = members["dissipation_resolved"][:] != 0 if "dissipation_resolved" in members else [True] * count
    # each reason apart, as `rotorsweep run` counts them: a symmetry-limited or departed member is not
    # resolved, but is not counted among those whose error is merely too large
    counts = {
        "dissipation_resolved": sum(1 for k in range(count) if ok[k] and not resolved[k]
                                    and not flag["symmetry_limited"][k] and not flag["shadow_departed"][k]),
        "symmetry_limited": sum(1 for k in range(count) if ok[k] and flag["symmetry_limited"][k]),
        "shadow_departed": sum(1 for k in range(count) if ok[k] and flag["shadow_departed"][k]),
    }
    texts = {
        "dissipation_resolved": "whose D is not resolved (dissipation_error >= 0.1 |D|)",
        "symmetry_limited": "whose D an asymmetry of the rows below rtol decides (symmetry-limited, "
                            f"{sum(1 for k in range(count) if ok[k] and flag['symmetry_held'][k])} of them "
                            "held on a symmetric set without slipping: no error bounds D, not counted as "
                            "resolved; give the scene disorder or a temperature above rtol)",
        "shadow_departed": "whose shadow run reached another attractor (no error estimate; give the scene "
                           "disorder or a temperature above rtol)",
    }
    for column, flagged in counts.items():
        if flagged:
            write(f"warning: {flagged} members {texts[column]}; see /members/{column}\n")
    if "slip_jumps" in members:
        regime = [r.decode() if isinstance(r, bytes) else str(r) for r in members["regime"][:]]
        untold = sum(1 for k, r, j in zip(ok, regime, members["slip_jumps"][:]) if k and r == "CP" and j != j)
        if untold:
            write(f"warning: {untold} CP members whose slips could not be told jumps or smooth (their "
                             "slower rerun at g/10 did not finish): slip_jumps and slip_smooth are NaN; see "
                             "/members/slip_jumps\n")


def report_kept(kept, total, path, command):
    """The line `rotorsweep run` (`command`: "run" or "slider") prints when it stops early: the finished
    members kept in the partial file (kept None: none kept)."""
    if kept is None:
        return
    write(f"\nstopped: {kept} of {total} members done, kept in {path}.partial (not a result: "
                     f"complete = FALSE); continue with `rotorsweep {command} SCENE -o {path} --resume`\n")
