#!/usr/bin/env python3
"""Turns BenchProxyTick's JSON into a PNG of per-tick solve time against triangle count and a
markdown table, with the targets of the proxy-solver issue marked.

Usage: plot_proxy_benchmarks.py RESULTS.json --figure PNG --table TABLE.md
"""
import argparse
import json

import matplotlib

matplotlib.use("Agg")  # no display on CI machines
import matplotlib.pyplot as plt  # noqa: E402

MEDIAN_TARGET_NS = 2000.0  # sliding contact at 1.3M triangles, median
P999_TARGET_NS = 20000.0  # and p99.9


def load(path):
    with open(path) as f:
        data = json.load(f)
    rows, effects = [], []
    for b in data["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
            continue
        name = b["name"].split("/")
        if "SurfaceEffects" in name[0]:
            effects.append(b)
            continue
        mesh = "skull (CT, shared)" if "Skull" in name[0] else "icosphere %s" % name[1]
        rows.append(dict(b, mesh=mesh))
    rows.sort(key=lambda r: r["triangles"])
    return data["context"], rows, effects


def machine(context):
    cpus = context.get("num_cpus", "?")
    mhz = context.get("mhz_per_cpu", "?")
    return "%s CPUs at %s MHz, %s" % (cpus, mhz, context.get("date", ""))


def plot(context, rows, figure):
    fig, ax = plt.subplots(figsize=(9.5, 4.8))
    x = [r["triangles"] for r in rows]
    for key, label, style in [
        ("contact_median_ns", "median (ticks in contact)", "o-"),
        ("contact_p99_ns", "p99 (ticks in contact)", "s--"),
        ("contact_p999_ns", "p99.9 (ticks in contact)", "^:"),
    ]:
        ax.plot(x, [r[key] / 1000.0 for r in rows], style, label=label)
    for r in rows:
        ax.annotate(r["mesh"], (r["triangles"], r["contact_median_ns"] / 1000.0),
                    textcoords="offset points", xytext=(4, -12), fontsize=7)
    ax.axhline(MEDIAN_TARGET_NS / 1000.0, color="green", lw=0.8, label="target: median 2 us")
    ax.axhline(P999_TARGET_NS / 1000.0, color="red", lw=0.8, label="target: p99.9 20 us")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("triangles")
    ax.set_ylabel("whole proxy tick [us]")
    ax.set_title("Proxy tick in sliding contact (press and stroke, r = 1 mm, 1 kHz)\n"
                 + machine(context), fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(figure, dpi=120)


def table(rows, path):
    lines = [
        "| mesh | triangles | ticks in contact | median / p99 / p99.9 in contact [us] | "
        "median / p99 / p99.9 / max all ticks [us] | iterations per tick | "
        "triangles tested per tick |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            "| %s | %d | %.0f%% | %.2f / %.1f / %.1f | %.2f / %.1f / %.1f / %.1f | %.2f | %.1f |"
            % (r["mesh"], r["triangles"], 100.0 * r["contact_fraction"],
               r["contact_median_ns"] / 1e3, r["contact_p99_ns"] / 1e3,
               r["contact_p999_ns"] / 1e3, r["tick_median_ns"] / 1e3, r["tick_p99_ns"] / 1e3,
               r["tick_p999_ns"] / 1e3, r["tick_max_ns"] / 1e3, r["iterations_per_tick"],
               r["triangles_tested_per_tick"]))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def effects_table(effects, path):
    """The cost of each surface effect on the same path (pay for what you use)."""
    if not effects:
        return
    plain = effects[0]["contact_median_ns"]
    lines = [
        "| surface | median / p99 / p99.9 in contact [us] | vs plain (median) | iterations per tick "
        "| triangles tested per tick |",
        "|---|---|---|---|---|",
    ]
    for b in effects:
        lines.append("| %s | %.2f / %.1f / %.1f | %.2fx | %.2f | %.1f |" % (
            b.get("label", b["name"]), b["contact_median_ns"] / 1e3, b["contact_p99_ns"] / 1e3,
            b["contact_p999_ns"] / 1e3, b["contact_median_ns"] / plain, b["iterations_per_tick"],
            b["triangles_tested_per_tick"]))
    with open(path, "a") as f:
        f.write("\nSurface effects on the 1.3M-triangle icosphere, same path:\n\n")
        f.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("results")
    parser.add_argument("--figure", required=True)
    parser.add_argument("--table", required=True)
    args = parser.parse_args()
    context, rows, effects = load(args.results)
    plot(context, rows, args.figure)
    table(rows, args.table)
    effects_table(effects, args.table)


if __name__ == "__main__":
    main()
