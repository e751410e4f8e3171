#!/usr/bin/env python3
"""The threaded runtime's servo loop on the real clock: two runs of Testing/Benchmarks'
ServoLoopJitter (by default 60 s at 4 kHz on the 1.5M-triangle skull), one plain and one with a
1.5M-triangle model swap half way. Writes Documentation/Figures/servo_jitter.png (the servo
period histograms), Documentation/Figures/servo_jitter.json (both reports) and
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
    with open(histogram) as f:
        report["histogram"] = [(int(r["period_us"]), int(r["ticks"])) for r in csv.DictReader(f)]
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

    figure, axis = plt.subplots(figsize=(8, 4.5))
    for name, colour in (("plain", "tab:blue"), ("swap", "tab:orange")):
        # Every 1 us bin, empty ones too, so that the log axis leaves gaps where no tick fell
        # instead of drawing a line across them.
        counts = dict(reports[name]["histogram"])
        edges = list(range(0, max(counts) + 2))
        heights = [counts.get(b, 0) or float("nan") for b in edges]
        axis.step(edges, heights, where="post", color=colour,
                  label="%s (p99 jitter %.1f us, %d missed)" % (
                      "no swap" if name == "plain" else "1.5M-triangle swap at %g s" % (
                          arguments.seconds / 2),
                      reports[name]["servo"]["jitter_us"]["p99"],
                      reports[name]["servo"]["missed_deadlines"]))
    axis.axvline(nominal, color="grey", linestyle=":", label="nominal period %.0f us" % nominal)
    axis.set_yscale("log")
    axis.set_xlabel("servo period (us, 1 us bins)")
    axis.set_ylabel("ticks")
    axis.set_xlim(0, max(3 * nominal, 1))
    axis.set_title("Servo loop at %g Hz for %g s, skull 1.5M triangles" % (
        arguments.rate, arguments.seconds))
    axis.legend(fontsize=8)
    figure.text(0.01, 0.01, where + "  |  /usr/bin/python3 Tools/servo_jitter.py", fontsize=7,
                color="grey")
    figure.tight_layout(rect=(0, 0.03, 1, 1))
    figure.savefig(os.path.join(figures, "servo_jitter.png"), dpi=110)

    for report in reports.values():
        report.pop("histogram")
    with open(os.path.join(figures, "servo_jitter.json"), "w") as f:
        json.dump({"machine": where, "reports": reports}, f, indent=2)

    rows = ["| run | loop | ticks | p50 / p99 / p99.9 / max jitter (us) | missed deadlines | "
            "ticks over budget | longest tick (us) |", "|---|---|---|---|---|---|---|"]
    for name, report in reports.items():
        for loop in ("servo", "proxy"):
            s = report[loop]
            j = s["jitter_us"]
            rows.append("| %s | %s | %d | %.1f / %.1f / %.1f / %.1f | %d | %d | %.1f |" % (
                "no swap" if name == "plain" else "swap", loop, s["ticks"], j["p50"], j["p99"],
                j["p99.9"], j["max"], s["missed_deadlines"], s["over_budget_ticks"],
                s["max_work_us"]))
    swap = reports["swap"]["swap"]
    text = ("Measured on %s; scheduling: %s.\n\n" % (where, reports["plain"]["scheduling"]) +
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
