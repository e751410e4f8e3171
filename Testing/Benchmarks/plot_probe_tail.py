#!/usr/bin/python3
"""Plots the tail of BenchProbeTail's per-tick solve times and writes its table.

The tail figure shows, log-log, the fraction of ticks slower than t: on the left one curve per
shared mesh at one proxy radius (seeds pooled, no budget); in the middle the shared person-like
paths and on the right all meshes pooled per radius, each without a budget (solid) and with the
servo-safe budget (dashed). The iteration figure shows the cost of one iteration against r over
the mesh's median edge length, log-log, with a slope-2 line: an iteration that tests every
triangle within reach of the proxy would grow as (r / edge)^2. The table gives median, p99,
p99.9 and max per case, what the budget cost, and the per-iteration cost.

Usage: plot_probe_tail.py BENCH.json --figure OUT.png --iteration-figure OUT.png --table OUT.md
                          --machine TEXT [--radius M]
"""
import argparse
import json
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def microseconds(ns):
    return ns / 1e3


def plot_tail(axes, points, label, style="-", color=None):
    times = [microseconds(t) for t, _ in points]
    fractions = [f for _, f in points]
    # A fraction of 0 (the slowest tick) has no place on a log axis: the curve stops at 1 / N.
    kept = [(t, f) for t, f in zip(times, fractions) if f > 0]
    if kept:
        lines = axes.step([t for t, _ in kept], [f for _, f in kept], style, where="post",
                          label=label, linewidth=1.2, color=color)
        return lines[0].get_color()
    return color


def plot_pair(axes, stats, label):
    """The unbudgeted tail solid and the budgeted one dashed, in one colour so they pair up."""
    color = plot_tail(axes, stats["tail"], label)
    plot_tail(axes, stats["budgeted"]["tail"], f"{label}, budget", "--", color)


def row(name, radius, stats, extra=""):
    contact = stats["contact_solve_ns"]
    budgeted = stats["budgeted"]
    budget = budgeted["budget"]
    return (f"| {name}{extra} | {radius * 1e3:g} | {stats['ticks']:,} | {stats['contact_ticks']:,} | "
            f"{microseconds(contact['median']):.2f} | {microseconds(contact['p99']):.1f} | "
            f"{microseconds(contact['p99.9']):.1f} | {microseconds(contact['max']):.1f} | "
            f"{microseconds(stats['solve_ns']['max']):.1f} | {stats['iterations']['p99.9']:g} | "
            f"{stats['iterations']['max']:g} | {stats['triangles_tested']['mean']:.1f} | "
            f"{stats['triangles_tested']['max']:g} | "
            f"{microseconds(budgeted['solve_ns']['p99.9']):.1f} | "
            f"{microseconds(budgeted['solve_ns']['max']):.1f} | "
            f"{100 * budget['limited_fraction']:.2f} | {budget['residual_m']['max'] * 1e3:.3g} | "
            f"{budget['recovery_ticks']['max']:g} |")


def slope(series):
    """Least-squares slope of log(ns per iteration) on log(r / edge); None below two points."""
    points = [(math.log(s["r_over_edge"]), math.log(s["solve_ns_per_iteration"]))
              for s in series if s["r_over_edge"] > 0 and s["solve_ns_per_iteration"] > 0]
    if len(points) < 2:
        return None
    mean_x = sum(x for x, _ in points) / len(points)
    mean_y = sum(y for _, y in points) / len(points)
    spread = sum((x - mean_x) ** 2 for x, _ in points)
    if spread == 0:
        return None
    return sum((x - mean_x) * (y - mean_y) for x, y in points) / spread


def plot_iteration_cost(report, path, title):
    figure, axes = plt.subplots(figsize=(8, 6))
    markers = "osD^v<>pPX*h"
    all_x = []
    all_y = []
    for k, mesh in enumerate(report["meshes"]):
        series = [s for s in mesh["iteration_cost"]
                  if s["r_over_edge"] > 0 and s["solve_ns_per_iteration"] > 0]
        x = [s["r_over_edge"] for s in series]
        y = [microseconds(s["solve_ns_per_iteration"]) for s in series]
        all_x += x
        all_y += y
        axes.plot(x, y, markers[k % len(markers)] + "-", label=mesh["mesh"], linewidth=0.8,
                  markersize=5)
    if all_x:
        # The slope-2 reference goes through the geometric mean of all points, so that it sits
        # among them whatever the machine's speed; one decade of r / edge wide, so that its
        # hundredfold rise does not flatten the points into the bottom of the axes.
        x0 = math.exp(sum(math.log(x) for x in all_x) / len(all_x))
        y0 = math.exp(sum(math.log(y) for y in all_y) / len(all_y))
        xs = [max(min(all_x), x0 / math.sqrt(10)), min(max(all_x), x0 * math.sqrt(10))]
        axes.plot(xs, [y0 * (x / x0) ** 2 for x in xs], "k:", linewidth=1.2,
                  label="slope 2: (r / edge)^2")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("proxy radius r / median edge length of the mesh")
    axes.set_ylabel("proxy update time per iteration (us)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=7)
    axes.set_title(title, fontsize=9)
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def platform_floor(report):
    """The busy loop BenchProbeTail runs first: the stalls no solver can avoid on this machine."""
    floor = report.get("platform_floor")
    if floor is None:
        return "Platform floor: not measured by this BenchProbeTail."
    return (
        f"Platform floor, measured first in the same run: a busy loop that only reads the clock "
        f"for {floor['seconds']:.0f} s was stalled {floor['stalls_over_30us_per_s']:.0f} times a "
        f"second for over 30 us and {floor['stalls_over_100us_per_s']:.1f} times for over "
        f"100 us, the longest {microseconds(floor['longest_stall_ns']):.0f} us, "
        f"{100 * floor['stalled_fraction']:.2f} % of the time in all. A tick that meets such a "
        "stall is that much slower whatever the solver does: the maxima below, and the p99.9 of "
        "ticks that take tens of microseconds, include them.")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("bench")
    parser.add_argument("--figure", required=True)
    parser.add_argument("--iteration-figure", required=True)
    parser.add_argument("--table", required=True)
    parser.add_argument("--machine", required=True)
    parser.add_argument("--radius", type=float, default=0.002,
                        help="proxy radius of the per-mesh curves, metres (default 0.002)")
    args = parser.parse_args()
    with open(args.bench) as f:
        report = json.load(f)

    figure, (by_mesh, by_path, by_radius) = plt.subplots(1, 3, figsize=(18, 5.5), sharey=True)
    for stats in report["pooled"]:
        if stats["mesh"] != "all meshes" and abs(stats["radius_m"] - args.radius) < 1e-12:
            plot_tail(by_mesh, stats["tail"], stats["mesh"])
    for stats in report["shared_paths"]:
        plot_pair(by_path, stats, f"{stats['path']} (r {stats['radius_m'] * 1e3:g} mm)")
    for stats in report["pooled"]:
        if stats["mesh"] == "all meshes":
            plot_pair(by_radius, stats, f"r = {stats['radius_m'] * 1e3:g} mm")
    budget_us = microseconds(report["budget_s"] * 1e9)
    for axes in (by_path, by_radius):
        axes.axvline(budget_us, color="grey", linewidth=0.8, alpha=0.6)
    seeds = report["seeds"]
    by_mesh.set_title(f"probe paths at r = {args.radius * 1e3:g} mm ({seeds} seed(s) pooled), "
                      "no budget", fontsize=10)
    by_path.set_title(f"shared paths: no budget (solid), {budget_us:g} us budget (dashed)",
                      fontsize=10)
    by_radius.set_title(f"all meshes pooled per radius: no budget, {budget_us:g} us (dashed)",
                        fontsize=10)
    for axes in (by_mesh, by_path, by_radius):
        axes.set_xscale("log")
        axes.set_yscale("log")
        axes.set_xlabel("proxy update time per tick t (us)")
        axes.grid(True, which="both", alpha=0.3)
        axes.legend(fontsize=7)
    by_mesh.set_ylabel("fraction of ticks slower than t")
    mode = "quick run" if report["quick"] else "full run"
    figure.suptitle(f"Worst ticks on person-like probing (BenchProbeTail, {mode}, lockstep at "
                    f"{report['rate_hz']:g} Hz)\n{args.machine}", fontsize=10)
    figure.tight_layout()
    figure.savefig(args.figure, dpi=110)
    plot_iteration_cost(report, args.iteration_figure,
                        f"Cost of one proxy iteration against r / edge (BenchProbeTail, {mode}, "
                        f"no budget, seeds pooled)\n{args.machine}")

    header = ("| case | radius (mm) | ticks | contact ticks | contact median (us) | p99 (us) | "
              "p99.9 (us) | max (us) | max, all ticks (us) | iterations p99.9 | iterations max | "
              "triangles tested mean | triangles tested max | budgeted p99.9, all ticks (us) | "
              "budgeted max, all ticks (us) | limited (%) | residual max (mm) | "
              "recovery max (ticks) |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
              "---:|---:|")
    lines = [
        "# Probe tail: per-tick proxy update time on person-like probing",
        "",
        "Generated by Testing/Benchmarks/plot_probe_tail.py from BenchProbeTail "
        "(Tools/tail-report.sh); do not edit by hand.",
        "",
        f"Machine: {args.machine}. {mode.capitalize()}: {seeds} seed(s) per mesh and radius, "
        f"pooled; radii {', '.join(f'{r * 1e3:g}' for r in report['radii_m'])} mm; "
        f"{report['run_s']:.0f} s in all. Times are the solver's own per-tick `solve_ns`; "
        "median, p99, p99.9 and max are over the ticks in contact (the slowest tick of the whole "
        "run is the next column). Figure: [Figures/probe_tail.png](Figures/probe_tail.png).",
        "",
        f"Every case also runs with the servo-safe work budget of the real-time runtime "
        f"({microseconds(report['budget_s'] * 1e9):g} us per tick); the `budgeted` columns are "
        "over all of that run's ticks. *Limited* is the share of ticks the budget stopped before "
        "the proxy settled; *residual* is how far such a tick ended from where the same tick, "
        "from the same start, ends without a budget (as `proxima run --summary` measures it); "
        "*recovery* is the length in ticks of a run of limited ticks, up to the first tick that "
        "is not limited. The budget is checked between iterations, so a tick can pass it by one "
        "iteration's time.",
        "",
        platform_floor(report),
        "",
        "## Probe paths (`proxima path probe`), per mesh and radius",
        "",
        header,
    ]
    for stats in report["pooled"]:
        name = stats["mesh"]
        lines.append(row(f"**{name}**" if name == "all meshes" else name, stats["radius_m"], stats))
    lines += ["", "## The shared person-like paths, at their README's scale and radius", "", header]
    for stats in report["shared_paths"]:
        lines.append(row(stats["path"], stats["radius_m"], stats, f" ({stats['mesh']})"))
    lines += [
        "",
        "## Cost of one iteration against r / median edge length",
        "",
        "Probe paths without a budget, seeds pooled: solve time and triangles tested over the "
        "iterations of ticks that ran at least one (the tick's fixed costs are included, so the "
        "cost at small r / edge is mostly overhead). The edge length is the median of the "
        "mesh's distinct edges after scaling. The slope is the least-squares slope of log cost "
        "on log(r / edge) over the radii; an iteration that tests every triangle within reach "
        "would approach 2. Figure: "
        "[Figures/probe_iteration_cost.png](Figures/probe_iteration_cost.png).",
        "",
        "| mesh | triangles | median edge (mm) | radius (mm) | r / edge | us per iteration | "
        "triangles tested per iteration | slope |",
        "|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for mesh in report["meshes"]:
        fitted = slope(mesh["iteration_cost"])
        for k, point in enumerate(mesh["iteration_cost"]):
            # The mesh's columns and its slope once, on its first row.
            first = k == 0
            lines.append(
                f"| {mesh['mesh'] if first else ''} | "
                f"{format(mesh['triangles'], ',') if first else ''} | "
                f"{format(mesh['median_edge_m'] * 1e3, '.3g') if first else ''} | "
                f"{point['radius_m'] * 1e3:g} | "
                f"{point['r_over_edge']:.3g} | "
                f"{microseconds(point['solve_ns_per_iteration']):.3f} | "
                f"{point['triangles_tested_per_iteration']:.2f} | "
                f"{'' if not first or fitted is None else f'{fitted:.2f}'} |")
    with open(args.table, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
