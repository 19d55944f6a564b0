#!/usr/bin/env python3
"""Figures of an `imlab run` CSV (read from stdin) that `imlab metrics` does not give.

  imlab run SCENARIO | scripts/trace_stats.py rms-after T
      RMS and peak of ω − ω_d over t ≥ T (s), and the peak stator current |i_s| there (A).
  imlab run SCENARIO | scripts/trace_stats.py load-step T [BAND]
      After a load step at T (s) on a constant reference: the largest dip of ω below the
      reference, the error at the last sample, and the recovery time: from T to the first sample
      after which |ω − ω_d| stays within BAND (rad/s, default 0.5) to the end ("never left" when
      it stays within from T on, "never" when it is outside at the end).
"""
import csv
import math
import sys


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("rms-after", "load-step"):
        sys.exit(__doc__)
    kind, start = sys.argv[1], float(sys.argv[2])
    band = float(sys.argv[3]) if len(sys.argv) > 3 else 0.5
    rows, currents = [], []
    for r in csv.DictReader(sys.stdin):
        rows.append((float(r["t"]), float(r["omega_err"])))
        currents.append(math.hypot(float(r["i_sa"]), float(r["i_sb"])))
    # Half a sample of slack, so that T given in round figures includes the sample at T.
    ts = rows[1][0] - rows[0][0]
    after = [(t, e) for t, e in rows if t >= start - 0.5 * ts]
    if not after:
        sys.exit(f"no sample at t ≥ {start} s")
    if kind == "rms-after":
        rms = math.sqrt(sum(e * e for _, e in after) / len(after))
        peak = max(abs(e) for _, e in after)
        current = max(currents[len(rows) - len(after):])
        print(f"rms={rms:.4g} peak={peak:.4g} current_peak={current:.4g} samples={len(after)}")
        return
    dip = min(e for _, e in after)
    inside_from = None
    for t, e in reversed(after):
        if abs(e) >= band:
            break
        inside_from = t
    if inside_from is None:
        recovery = "never"
    elif inside_from == after[0][0]:
        recovery = "never left"
    else:
        recovery = f"{inside_from - start:.4g} s"
    print(f"dip={dip:.4g} final={rows[-1][1]:.4g} recovery={recovery} (band ±{band} rad/s)")


if __name__ == "__main__":
    main()
