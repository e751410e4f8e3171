#!/usr/bin/env python3
"""Fails unless a `proxima run --realtime` trace agrees with the lockstep trace of the same run:
every realtime row is a lockstep tick with the same time and finger, and the same proxy to 1 nm
(bit for bit until the proxy loop first skips a sample; after a skip only the steps the proxy
took differ). How many ticks a real-time run keeps is not known in advance (a late servo skips
ticks, more of them on a loaded machine), so the rows are not counted; at least one of them must
be in contact, so that the comparison covers the proxy on the surface. The realtime run must have
no tick budget (--tick-budget none): a time budget stops ticks wherever the clock says.

    compare_realtime_trace.py LOCKSTEP.csv REALTIME.csv"""
import csv
import sys


def main():
    lockstep = {int(row["tick"]): row for row in csv.DictReader(open(sys.argv[1]))}
    realtime = list(csv.DictReader(open(sys.argv[2])))
    worst = 0.0
    in_contact = 0
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
        in_contact += int(row["contacts"]) > 0
        if gap > 1e-9:
            sys.exit("tick %d: the proxy is %.3g m from lockstep's" % (tick, gap))
    if in_contact == 0:
        sys.exit("%s: none of its %d rows is in contact" % (sys.argv[2], len(realtime)))
    print("%d of %d ticks (%d in contact), worst proxy difference %.3g m"
          % (len(realtime), len(lockstep), in_contact, worst))


if __name__ == "__main__":
    main()
