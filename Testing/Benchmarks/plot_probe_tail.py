#!/usr/bin/python3
"""Plots BenchProbeTail's report: the worst ticks, the budget sweep, and the cost of an iteration.

Every time here is a tick's replayed work (the least wall time over repeats of the same update
from the same solver state), unless a column says "single run" (the trace's solve_ns, the
platform's stalls included).

The tail figure shows, log-log, the fraction of ticks whose work exceeds t: on the left one curve
per shared mesh at one proxy radius (seeds pooled, no budget); in the middle the shared person-like
paths and on the right all meshes pooled per radius, each without a budget (solid) and with the
real-time default budget (dashed), the single run without a budget dotted. The budget figure is
run time against error: for each iteration budget of the sweep, the work (p99.9, max), the share
of limited ticks, their recovery and their force error against the same tick settled without a
budget, on the shared paths and the whole probe corpus. The iteration figure shows the cost of one
iteration against r over the mesh's median edge length, log-log, with a slope-2 line.

The tables go to the tail table (every case) and, between the markers `<!-- budget-sweep:begin -->`
and `<!-- budget-sweep:end -->`, into the performance page.

Usage: plot_probe_tail.py BENCH.json --figure OUT.png --budget-figure OUT.png
                          --iteration-figure OUT.png --table OUT.md --performance-page PAGE.md
                          --machine TEXT [--radius M]
"""
import argparse
import json
import math
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

BEGIN_MARKER = "<!-- budget-sweep:begin -->"
END_MARKER = "<!-- budget-sweep:end -->"


def microseconds(ns):
    return ns / 1e3


def plot_tail(axes, points, label, style="-", color=None, width=1.2):
    times = [microseconds(t) for t, _ in points]
    fractions = [f for _, f in points]
    # A fraction of 0 (the slowest tick) has no place on a log axis: the curve stops at 1 / N.
    kept = [(t, f) for t, f in zip(times, fractions) if f > 0]
    if kept:
        lines = axes.step([t for t, _ in kept], [f for _, f in kept], style, where="post",
                          label=label, linewidth=width, color=color)
        return lines[0].get_color()
    return color


def default_run(report, stats):
    return stats["budgets"][report["default_budget"]]


def plot_group(axes, report, stats, label):
    """Work without a budget solid, with the default budget dashed, the single run dotted."""
    color = plot_tail(axes, stats["work_tail"], label)
    plot_tail(axes, default_run(report, stats)["work_tail"], f"{label}, default budget", "--",
              color)
    plot_tail(axes, stats["tail"], f"{label}, single run", ":", color, 0.8)


def budget_names(report):
    return ["none" if b == 0 else f"{b}it" for b in report["budgets_it"]]


def run_of(stats, name):
    return stats if name == "none" else stats["budgets"][name]


def sweep_groups(report):
    """The series of the budget figure and table: each shared path, then the whole corpus."""
    groups = [(f"{s['path']} (r {s['radius_m'] * 1e3:g} mm)", s) for s in report["shared_paths"]]
    for stats in report["pooled"]:
        if stats["mesh"] == "all meshes" and stats["radius_m"] == 0:
            groups.append(("probe corpus, every mesh, radius and seed", stats))
    return groups


def plot_budget_sweep(report, path, title):
    names = budget_names(report)
    # "none" sits one doubling right of the largest budget, labelled as such.
    positions = [2 * max(report["budgets_it"]) if n == "none" else int(n[:-2]) for n in names]
    figure, panels = plt.subplots(2, 2, figsize=(14, 10))
    (work, limited), (recovery, error) = panels
    for label, stats in sweep_groups(report):
        runs = [run_of(stats, n) for n in names]
        color = work.plot(positions, [microseconds(r["work_ns"]["max"]) for r in runs], "o-",
                          label=f"{label}: max", linewidth=1.2)[0].get_color()
        work.plot(positions, [microseconds(r["work_ns"]["p99.9"]) for r in runs], "s--",
                  color=color, label=f"{label}: p99.9", linewidth=0.9)
        budgeted = [(x, r) for x, r in zip(positions, runs) if "budget" in r]
        xs = [x for x, _ in budgeted]
        limited.plot(xs, [100 * r["budget"]["limited_fraction"] for _, r in budgeted], "o-",
                     color=color, label=label)
        recovery.plot(xs, [r["budget"]["recovery_ticks"]["max"] for _, r in budgeted], "o-",
                      color=color, label=f"{label}: max")
        recovery.plot(xs, [r["budget"]["recovery_ticks"]["p99"] for _, r in budgeted], "s--",
                      color=color, label=f"{label}: p99")
        error.plot(xs, [r["budget"]["force_angle_deg"]["median"] for _, r in budgeted], "o-",
                   color=color, label=f"{label}: median")
        error.plot(xs, [r["budget"]["force_angle_deg"]["p99"] for _, r in budgeted], "s--",
                   color=color, label=f"{label}: p99")
    default_position = int(report["default_budget"][:-2])
    for axes in (work, limited, recovery, error):
        axes.set_xscale("log", base=2)
        axes.set_xticks(positions)
        axes.set_xticklabels(names)
        axes.axvline(default_position, color="grey", linewidth=0.8, alpha=0.6)
        axes.grid(True, which="both", alpha=0.3)
        axes.set_xlabel("iteration budget per tick (grey: the real-time default)")
    work.set_yscale("log")
    work.set_ylabel("replayed work per tick (us)")
    work.set_title("run time: the slowest ticks", fontsize=10)
    # Symmetric-log axes, for the zeros a log axis cannot show; no quantity here is negative.
    for axes, threshold, label, title_text in (
            (limited, 0.01, "ticks the budget limited (%)", "how often the budget bites"),
            (recovery, 1, "ticks until the proxy settles again",
             "recovery of a run of limited ticks"),
            (error, 0.1, "force direction error of limited ticks (degrees)",
             "error: against the same tick settled without a budget")):
        axes.set_yscale("symlog", linthresh=threshold)
        axes.set_ylim(bottom=0)
        axes.set_ylabel(label)
        axes.set_title(title_text, fontsize=10)
    work.legend(fontsize=6, ncol=2)
    error.legend(fontsize=6, ncol=2)
    figure.suptitle(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(path, dpi=100)


def slope(series):
    """Least-squares slope of log(ns per iteration) on log(r / edge); None below two points."""
    points = [(math.log(s["r_over_edge"]), math.log(s["work_ns_per_iteration"]))
              for s in series if s["r_over_edge"] > 0 and s["work_ns_per_iteration"] > 0]
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
                  if s["r_over_edge"] > 0 and s["work_ns_per_iteration"] > 0]
        x = [s["r_over_edge"] for s in series]
        y = [microseconds(s["work_ns_per_iteration"]) for s in series]
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
    axes.set_ylabel("replayed work per iteration (us)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=7)
    axes.set_title(title, fontsize=9)
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def platform_floor(report):
    """The busy loop BenchProbeTail runs first: the stalls no solver can avoid on this machine."""
    floor = report["platform_floor"]
    return (
        f"Platform floor, measured first in the same run: a busy loop that only reads the clock "
        f"for {floor['seconds']:.0f} s was stalled {floor['stalls_over_30us_per_s']:.0f} times a "
        f"second for over 30 us and {floor['stalls_over_100us_per_s']:.1f} times for over "
        f"100 us, the longest {microseconds(floor['longest_stall_ns']):.0f} us, "
        f"{100 * floor['stalled_fraction']:.2f} % of the time in all. A single run of a tick "
        "that meets such a stall is that much slower whatever the solver does; the replayed "
        "work is the least of several runs, which a stall rarely hits all of.")


def tail_row(report, name, radius, stats, extra=""):
    contact = stats["contact_work_ns"]
    work = stats["work_ns"]
    budgeted = default_run(report, stats)
    budget = budgeted["budget"]
    return (f"| {name}{extra} | {radius * 1e3:g} | {stats['ticks']:,} | {stats['contact_ticks']:,} | "
            f"{microseconds(contact['median']):.2f} | {microseconds(work['p99']):.1f} | "
            f"{microseconds(work['p99.9']):.1f} | {microseconds(work['max']):.1f} | "
            f"{microseconds(stats['solve_ns']['p99.9']):.1f} | "
            f"{microseconds(stats['solve_ns']['max']):.1f} | "
            f"{stats['iterations']['p99.9']:g} | {stats['iterations']['max']:g} | "
            f"{stats['triangles_tested']['mean']:.1f} | "
            f"{microseconds(stats['per_iteration']['max_work_ns']):.1f} | "
            f"{microseconds(budgeted['work_ns']['p99.9']):.1f} | "
            f"{microseconds(budgeted['work_ns']['max']):.1f} | "
            f"{100 * budget['limited_fraction']:.2f} | {budget['recovery_ticks']['max']:g} |")


def sweep_rows(report):
    rows = ["| case | budget | contact median (us) | p99.9 (us) | max (us) | limited (%) | "
            "recovery p99 / max (ticks) | force angle median / p99 (deg) | "
            "force magnitude error median / p99 (%) | settled free: ticks, max force (N) |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for label, stats in sweep_groups(report):
        for k, name in enumerate(budget_names(report)):
            run = run_of(stats, name)
            cells = [label if k == 0 else "",
                     f"**{name}**" if name == report["default_budget"] else name,
                     f"{microseconds(run['contact_work_ns']['median']):.2f}",
                     f"{microseconds(run['work_ns']['p99.9']):.1f}",
                     f"{microseconds(run['work_ns']['max']):.1f}"]
            if "budget" in run:
                b = run["budget"]
                cells += [f"{100 * b['limited_fraction']:.2f}",
                          f"{b['recovery_ticks']['p99']:g} / {b['recovery_ticks']['max']:g}",
                          f"{b['force_angle_deg']['median']:.2f} / "
                          f"{b['force_angle_deg']['p99']:.1f}",
                          f"{100 * b['force_magnitude_error']['median']:.2f} / "
                          f"{100 * b['force_magnitude_error']['p99']:.1f}",
                          f"{b['settled_free_ticks']:,}, {b['settled_free_force_n']['max']:.3g}"]
            else:
                cells += ["", "", "", "", ""]
            rows.append("| " + " | ".join(cells) + " |")
    return rows


def write_atomically(path, text):
    folder = os.path.dirname(os.path.abspath(path))
    handle, temporary = tempfile.mkstemp(dir=folder, prefix=".plot_probe_tail.")
    with os.fdopen(handle, "w") as f:
        f.write(text)
    os.replace(temporary, path)


def replace_sweep_block(page, block):
    with open(page) as f:
        text = f.read()
    begin = text.find(BEGIN_MARKER)
    end = text.find(END_MARKER)
    if begin < 0 or end < begin:
        raise SystemExit(f"{page}: no {BEGIN_MARKER} ... {END_MARKER} block to fill")
    write_atomically(page, text[:begin + len(BEGIN_MARKER)] + "\n" + block + "\n" + text[end:])


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("bench")
    parser.add_argument("--figure", required=True)
    parser.add_argument("--budget-figure", required=True)
    parser.add_argument("--iteration-figure", required=True)
    parser.add_argument("--table", required=True)
    parser.add_argument("--performance-page", required=True)
    parser.add_argument("--machine", required=True)
    parser.add_argument("--radius", type=float, default=0.002,
                        help="proxy radius of the per-mesh curves, metres (default 0.002)")
    args = parser.parse_args()
    with open(args.bench) as f:
        report = json.load(f)
    mode = "quick run" if report["quick"] else "full run"
    seeds = report["seeds"]
    repeats = report["repeats"]
    default = report["default_budget"]

    figure, (by_mesh, by_path, by_radius) = plt.subplots(1, 3, figsize=(18, 5.5), sharey=True)
    for stats in report["pooled"]:
        if stats["mesh"] != "all meshes" and abs(stats["radius_m"] - args.radius) < 1e-12:
            plot_tail(by_mesh, stats["work_tail"], stats["mesh"])
    for stats in report["shared_paths"]:
        plot_group(by_path, report, stats, f"{stats['path']} (r {stats['radius_m'] * 1e3:g} mm)")
    for stats in report["pooled"]:
        if stats["mesh"] == "all meshes" and stats["radius_m"] > 0:
            plot_group(by_radius, report, stats, f"r = {stats['radius_m'] * 1e3:g} mm")
    by_mesh.set_title(f"probe paths at r = {args.radius * 1e3:g} mm ({seeds} seed(s) pooled), "
                      "no budget", fontsize=10)
    by_path.set_title(f"shared paths: no budget, {default} (dashed), single run (dotted)",
                      fontsize=10)
    by_radius.set_title(f"all meshes pooled per radius: no budget, {default} (dashed)",
                        fontsize=10)
    for axes in (by_mesh, by_path, by_radius):
        axes.set_xscale("log")
        axes.set_yscale("log")
        axes.set_xlabel(f"replayed work per tick t (us; least of {repeats} runs)")
        axes.grid(True, which="both", alpha=0.3)
        axes.legend(fontsize=6)
    by_mesh.set_ylabel("fraction of ticks slower than t")
    figure.suptitle(f"Worst ticks on person-like probing (BenchProbeTail, {mode}, lockstep at "
                    f"{report['rate_hz']:g} Hz)\n{args.machine}", fontsize=10)
    figure.tight_layout()
    figure.savefig(args.figure, dpi=110)
    plot_budget_sweep(report, args.budget_figure,
                      f"Run time against error: the iteration budget per tick (BenchProbeTail, "
                      f"{mode}, replayed work)\n{args.machine}")
    plot_iteration_cost(report, args.iteration_figure,
                        f"Cost of one proxy iteration against r / edge (BenchProbeTail, {mode}, "
                        f"no budget, seeds pooled)\n{args.machine}")

    header = ("| case | radius (mm) | ticks | contact ticks | contact median (us) | p99 (us) | "
              "p99.9 (us) | max (us) | single run p99.9 (us) | single run max (us) | "
              "iterations p99.9 | iterations max | triangles tested mean | "
              "most work per iteration (us) | "
              f"{default} p99.9 (us) | {default} max (us) | {default} limited (%) | "
              f"{default} recovery max (ticks) |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
              "---:|---:|")
    description = (
        f"Machine: {args.machine}. {mode.capitalize()}: {seeds} seed(s) per mesh and radius, "
        f"pooled; radii {', '.join(f'{r * 1e3:g}' for r in report['radii_m'])} mm; "
        f"{report['run_s']:.0f} s in all. Times are replayed work: the least wall time over "
        f"{repeats} runs of each tick's update from the same solver state; the single-run "
        "columns are the trace's `solve_ns`, stalls and all. The contact median is over the ticks "
        "in contact, the other quantiles over all ticks.")
    lines = [
        "# Probe tail: per-tick proxy work on person-like probing",
        "",
        "Generated by Testing/Benchmarks/plot_probe_tail.py from BenchProbeTail "
        "(Tools/tail-report.sh); do not edit by hand.",
        "",
        description + " Figure: [Figures/probe_tail.png](Figures/probe_tail.png).",
        "",
        f"The `{default}` columns are the real-time default budget (`--tick-budget default`): "
        "*limited* is the share of ticks it stopped before the proxy settled, *recovery* the "
        "length in ticks of a run of limited ticks up to the first that is not limited. "
        "*Most work per iteration* is the largest share of a tick's work per iteration over the "
        "ticks without a budget. The whole budget sweep is in "
        "[Performance.md](Performance.md).",
        "",
        platform_floor(report),
        "",
        "## Probe paths (`proxima path probe`), per mesh and radius",
        "",
        header,
    ]
    for stats in report["pooled"]:
        name = stats["mesh"]
        if name == "all meshes":
            if stats["radius_m"] == 0:
                continue
            name = f"**{name}**"
        lines.append(tail_row(report, name, stats["radius_m"], stats))
    lines += ["", "## The shared person-like paths, at their README's scale and radius", "", header]
    for stats in report["shared_paths"]:
        lines.append(tail_row(report, stats["path"], stats["radius_m"], stats,
                              f" ({stats['mesh']})"))
    lines += [
        "",
        "## Cost of one iteration against r / median edge length",
        "",
        "Probe paths without a budget, seeds pooled: replayed work and triangles tested over the "
        "iterations of ticks that ran at least one (the tick's fixed costs are included, so the "
        "cost at small r / edge is mostly overhead). The edge length is the median of the "
        "mesh's distinct edges after scaling. The slope is the least-squares slope of log cost "
        "on log(r / edge) over the radii; an iteration that tests every triangle within reach "
        "would approach 2. Figure: "
        "[Figures/probe_iteration_cost.png](Figures/probe_iteration_cost.png).",
        "",
        "| mesh | triangles | median edge (mm) | radius (mm) | r / edge | us per iteration | "
        "most us per iteration | triangles tested per iteration | slope |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|",
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
                f"{microseconds(point['work_ns_per_iteration']):.3f} | "
                f"{microseconds(point['max_work_ns_per_iteration']):.1f} | "
                f"{point['triangles_tested_per_iteration']:.2f} | "
                f"{'' if not first or fitted is None else f'{fitted:.2f}'} |")
    write_atomically(args.table, "\n".join(lines) + "\n")

    block = [
        "<!-- Generated by Testing/Benchmarks/plot_probe_tail.py (Tools/tail-report.sh); the "
        "block between the markers is replaced on every run: do not edit it by hand. -->",
        "",
        f"![run time against error: the iteration budget]"
        f"(Figures/{os.path.basename(args.budget_figure)})",
        "",
        description + " " + platform_floor(report),
        "",
        "Error of a limited tick: the same tick run again from the same solver state without a "
        "budget, and the spring force kp (proxy - finger) of the two compared: the angle between "
        "them and the relative difference of their magnitudes, over limited ticks whose settled "
        "force is at least 0.01 N (the others settle free: their count and largest force are the "
        f"last column). The real-time default, `--tick-budget default`, is **{default}**.",
        "",
    ] + sweep_rows(report)
    replace_sweep_block(args.performance_page, "\n".join(block))


if __name__ == "__main__":
    main()
