#!/usr/bin/env python3
"""The threaded runtime's servo loop on the real clock: two runs of Testing/Benchmarks'
ServoLoopJitter (by default 60 s at 4 kHz on the 1.5M-triangle skull), one plain and one with a
1.5M-triangle model swap half way, each just after a bare floor loop (same rate, scheduling and
clock, no work) of the same length in the same process. Writes
Documentation/Figures/servo_jitter.png (the servo's and the floor's period and wake-up latency
histograms), Documentation/Figures/servo_jitter.json (both reports) and
Documentation/ServoJitterTable.md (the table Threading.md includes).

    /usr/bin/python3 Tools/servo_jitter.py [--build build] [--seconds 60] [--rate 4000]

Run it on a quiet machine: other processes on the same cores show up as jitter."""
import argparse
import csv
import json
import os
import platform
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import proxima_runs  # noqa: E402,F401  (sets the Agg backend)
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores, Linux %s" % (model, os.cpu_count(), platform.release())


def run(binary, seconds, rate, swap, histogram):
    command = [binary, "--seconds", str(seconds), "--rate", str(rate), "--histogram", histogram]
    if swap:
        command.append("--swap")
    print("servo_jitter: " + " ".join(command), flush=True)
    report = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
    report["histogram"] = {}
    with open(histogram) as f:
        for r in csv.DictReader(f):
            report["histogram"].setdefault((r["loop"], r["quantity"]), {})[int(r["bin_us"])] = \
                int(r["count"])
    return report


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--rate", type=float, default=4000.0)
    arguments = parser.parse_args()
    binary = os.path.join(arguments.build, "Testing", "Benchmarks", "ServoLoopJitter")
    figures = os.path.join(ROOT, "Documentation", "Figures")
    reports = {
        "plain": run(binary, arguments.seconds, arguments.rate, False,
                     os.path.join(arguments.build, "servo_jitter_plain.csv")),
        "swap": run(binary, arguments.seconds, arguments.rate, True,
                    os.path.join(arguments.build, "servo_jitter_swap.csv")),
    }
    where = machine()
    nominal = 1e6 / arguments.rate

    figure, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    curves = (("plain", "servo", "tab:blue", "servo, no swap"),
              ("swap", "servo", "tab:orange", "servo, swap at %g s" % (arguments.seconds / 2)),
              ("plain", "floor", "black", "bare floor loop before no swap"),
              ("swap", "floor", "tab:grey", "bare floor loop before swap"))
    for axis, quantity, label, limit in (
            (axes[0], "period", "period (us, 1 us bins)", 3 * nominal),
            (axes[1], "wake_latency", "wake-up latency after the deadline (us, 1 us bins)",
             3 * nominal)):
        for name, loop, colour, text in curves:
            counts = reports[name]["histogram"].get((loop, quantity))
            if not counts:
                continue
            # Every 1 us bin, empty ones too, so that the log axis leaves gaps where no tick fell
            # instead of drawing a line across them.
            edges = list(range(0, max(counts) + 2))
            heights = [counts.get(b, 0) or float("nan") for b in edges]
            s = reports[name][loop]
            axis.step(edges, heights, where="post", color=colour,
                      linestyle="--" if loop == "floor" else "-",
                      label="%s: %d late of %d, %d missed" % (
                          text, s["late_wake_ups"], s["wake_ups"], s["missed_deadlines"]))
        if quantity == "period":
            axis.axvline(nominal, color="grey", linestyle=":", label="nominal %.0f us" % nominal)
        else:
            axis.axvline(nominal, color="grey", linestyle=":", label="one period: late beyond")
        axis.set_yscale("log")
        axis.set_xlabel(label)
        axis.set_ylabel("wake-ups")
        axis.set_xlim(0, max(limit, 1))
        axis.legend(fontsize=7)
    figure.suptitle("Servo loop at %g Hz for %g s, skull 1.5M triangles, beside a bare loop" % (
        arguments.rate, arguments.seconds))
    figure.text(0.01, 0.01, where + "  |  /usr/bin/python3 Tools/servo_jitter.py", fontsize=7,
                color="grey")
    figure.tight_layout(rect=(0, 0.03, 1, 1))
    figure.savefig(os.path.join(figures, "servo_jitter.png"), dpi=110)

    for report in reports.values():
        report.pop("histogram")
    with open(os.path.join(figures, "servo_jitter.json"), "w") as f:
        json.dump({"machine": where, "reports": reports}, f, indent=2)

    rows = ["| run | loop | wake-ups | p50 / p99 / p99.9 / max wake-up latency (us) | late wake-ups "
            "| missed deadlines | p50 / p99 / p99.9 / max jitter (us) | ticks over budget | "
            "longest tick (us) |", "|---|---|---|---|---|---|---|---|---|"]
    for name, report in reports.items():
        for loop in ("floor", "servo", "proxy"):
            s = report.get(loop)
            if not s:
                continue
            w = s["wake_latency_us"]
            j = s["jitter_us"]
            rows.append("| %s | %s | %d | %.0f / %.0f / %.0f / %.0f | %d (%.2f %%) | %d | "
                        "%.1f / %.1f / %.1f / %.1f | %d | %.1f |" % (
                            "no swap" if name == "plain" else "swap",
                            "bare floor loop" if loop == "floor" else loop, s["wake_ups"],
                            w["p50"], w["p99"], w["p99.9"], w["max"], s["late_wake_ups"],
                            100.0 * s["late_wake_ups"] / max(s["wake_ups"], 1),
                            s["missed_deadlines"], j["p50"], j["p99"], j["p99.9"], j["max"],
                            s["over_budget_ticks"], s["max_work_us"]))
    swap = reports["swap"]["swap"]
    text = ("Measured on %s, %g s per run at %g Hz, each run just after its bare floor loop of "
            "the same length; scheduling: %s.\n\n" % (
                where, arguments.seconds, arguments.rate, reports["plain"]["scheduling"]) +
            "\n".join(rows) + "\n\n" +
            "Model swap: %d triangles read and built in %.0f ms on the main thread, live in the "
            "proxy loop %.2f ms after publishing (%.0f ms from the start of the build); the "
            "install itself took %.1f us of one proxy tick.\n" % (
                swap["triangles"], swap["read_and_build_ms"],
                swap["build_to_live_ms"] - swap["read_and_build_ms"], swap["build_to_live_ms"],
                swap["install_in_proxy_loop_us"]))
    with open(os.path.join(ROOT, "Documentation", "ServoJitterTable.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
