#!/usr/bin/env python3
"""Fails unless a `proxima run --realtime` trace agrees with the lockstep trace of the same run:
every realtime row is a lockstep tick with the same time and finger, and the same proxy to 1 nm
(bit for bit until the proxy loop first skips a sample; after a skip only the steps the proxy
took differ). At least half the ticks must be there. The realtime run must have no tick budget
(--tick-budget none): a time budget stops ticks wherever the clock says.

    compare_realtime_trace.py LOCKSTEP.csv REALTIME.csv"""
import csv
import sys


def main():
    lockstep = {int(row["tick"]): row for row in csv.DictReader(open(sys.argv[1]))}
    realtime = list(csv.DictReader(open(sys.argv[2])))
    if len(realtime) * 2 < len(lockstep):
        sys.exit("%s: %d rows of %d ticks" % (sys.argv[2], len(realtime), len(lockstep)))
    worst = 0.0
    previous = -1
    for row in realtime:
        tick = int(row["tick"])
        if tick <= previous or tick not in lockstep:
            sys.exit("%s: tick %d out of order or not in the lockstep run" % (sys.argv[2], tick))
        previous = tick
        other = lockstep[tick]
        for key in ("t", "finger_x", "finger_y", "finger_z"):
            if row[key] != other[key]:
                sys.exit("tick %d: %s is %s, lockstep %s" % (tick, key, row[key], other[key]))
        gap = max(abs(float(row[k]) - float(other[k])) for k in ("proxy_x", "proxy_y", "proxy_z"))
        worst = max(worst, gap)
        if gap > 1e-9:
            sys.exit("tick %d: the proxy is %.3g m from lockstep's" % (tick, gap))
    print("%d of %d ticks, worst proxy difference %.3g m" % (len(realtime), len(lockstep), worst))


if __name__ == "__main__":
    main()
