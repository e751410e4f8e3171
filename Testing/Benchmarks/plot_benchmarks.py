#!/usr/bin/env python3
"""Turns BenchSphereTree's JSON into PNG plots and a markdown table (with the issue's targets).

Usage: plot_benchmarks.py RESULTS.json --figures DIR --table TABLE.md
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")  # no display on CI machines
import matplotlib.pyplot as plt  # noqa: E402

QUERIES = ["FirstContact", "Nearest", "GatherWithin"]
IMPLEMENTATIONS = ["SphereTree", "CgalAabb"]
LABELS = {"SphereTree": "Proxima sphere tree", "CgalAabb": "CGAL AABB tree"}
TARGET_MESH = "icosphere8"  # 1.3M triangles, 0.5 mm edges: where the targets apply


def to_ns(value, unit):
    return value * {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[unit]


def load(path):
    with open(path) as f:
        data = json.load(f)
    results = {}
    for b in data["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
            continue
        parts = b["name"].split("/")
        kind, impl, mesh = parts[0], parts[1], parts[2]
        entry = dict(b)
        entry["real_ns"] = to_ns(b["real_time"], b["time_unit"])
        entry["cpu_ns"] = to_ns(b["cpu_time"], b["time_unit"])
        results[(kind, impl, mesh)] = entry
    return data["context"], results


def meshes_in(results):
    order = ["icosphere5", "icosphere7", "icosphere8", "skull"]
    present = {m for (_, _, m) in results}
    return [m for m in order if m in present] + sorted(present - set(order))


def triangles(results, mesh):
    for impl in IMPLEMENTATIONS:
        entry = results.get(("Build", impl, mesh))
        if entry and "triangles" in entry:
            return int(entry["triangles"])
    return 0


def fmt_us(ns):
    return "–" if ns is None else f"{ns / 1e3:.2f}"


def series(results, meshes, key_of, value_of):
    """(triangles, value) pairs for the icospheres (a scaling line) and for the other meshes."""
    line, others = [], []
    for mesh in meshes:
        entry = results.get(key_of(mesh))
        if entry is None:
            continue
        value = value_of(entry)
        if value is None:
            continue
        point = (triangles(results, mesh), value, mesh)
        (line if mesh.startswith("icosphere") else others).append(point)
    return line, others


def draw(ax, line, others, color, marker, label, linestyle="-"):
    if line:
        ax.plot([p[0] for p in line], [p[1] for p in line], color=color, marker=marker,
                linestyle=linestyle, label=f"{label} (icospheres)")
    for x, y, mesh in others:
        ax.plot([x], [y], color=color, marker="*", markersize=11, linestyle="none",
                label=f"{label} ({mesh})")


COLORS = {"SphereTree": "tab:blue", "CgalAabb": "tab:red"}


def plot_queries(results, meshes, folder):
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
    for ax, query in zip(axes, QUERIES):
        for impl, marker in zip(IMPLEMENTATIONS, ["o", "s"]):
            for stat, style, name in [("median_ns", "-", "median"), ("p99_ns", ":", "p99")]:
                line, others = series(results, meshes, lambda m: (query, impl, m),
                                      lambda e: e[stat] / 1e3 if stat in e else None)
                draw(ax, line, others, COLORS[impl], marker, f"{LABELS[impl]} {name}", style)
        if query != "GatherWithin":
            ax.axhline(2.0, color="grey", linewidth=0.8, linestyle="--", label="target 2 µs")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("triangles")
        ax.set_ylabel("time per query [µs]")
        ax.set_title(query)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("Per-query time at r = 1 mm, 0.5 mm edges, segments ≤ 1 mm "
                 "(star: CT skull, 0.75 mm iso-surface)")
    fig.tight_layout()
    path = os.path.join(folder, "sphere_tree_queries.png")
    fig.savefig(path, dpi=110)
    return path


def plot_build(results, meshes, folder):
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.4))
    for impl, marker in zip(IMPLEMENTATIONS, ["o", "s"]):
        line, others = series(results, meshes, lambda m: ("Build", impl, m),
                              lambda e: e["real_ns"] / 1e6)
        draw(left, line, others, COLORS[impl], marker, LABELS[impl])
    left.axhline(1000, color="grey", linewidth=0.8, linestyle="--", label="target 1 s")
    left.set_xscale("log")
    left.set_yscale("log")
    left.set_xlabel("triangles")
    left.set_ylabel("build time [ms]")
    left.legend(fontsize=7)
    left.grid(True, which="both", alpha=0.3)
    line, others = series(results, meshes, lambda m: ("Build", "SphereTree", m),
                          lambda e: e.get("bytes_per_triangle"))
    draw(right, line, others, COLORS["SphereTree"], "o", LABELS["SphereTree"])
    right.axhline(64, color="grey", linewidth=0.8, linestyle="--", label="target 64 B")
    right.set_xscale("log")
    right.set_xlabel("triangles")
    right.set_ylabel("tree bytes per triangle")
    right.set_ylim(bottom=0)
    right.legend(fontsize=7)
    right.grid(True, which="both", alpha=0.3)
    fig.suptitle("Build (CGAL: tree and its k-d tree for distance queries)")
    fig.tight_layout()
    path = os.path.join(folder, "sphere_tree_build.png")
    fig.savefig(path, dpi=110)
    return path


def table(context, results, meshes):
    lines = []
    lines.append("| mesh | triangles | query | sphere tree median / p99 / mean [µs] | nodes visited | "
                 "triangles tested | CGAL AABB median / p99 / mean [µs] | CGAL triangles tested | "
                 "speed-up (median) |")
    lines.append("|---|---:|---|---|---:|---:|---|---:|---:|")
    for mesh in meshes:
        for query in QUERIES:
            ours = results.get((query, "SphereTree", mesh))
            theirs = results.get((query, "CgalAabb", mesh))
            if not ours and not theirs:
                continue

            def cell(e):
                if not e:
                    return "–"
                return f"{fmt_us(e.get('median_ns'))} / {fmt_us(e.get('p99_ns'))} / {fmt_us(e['cpu_ns'])}"

            speed = "–"
            if ours and theirs and ours.get("median_ns"):
                speed = f"{theirs['median_ns'] / ours['median_ns']:.1f}×"
            def count(e, key, digits):
                return f"{e[key]:.{digits}f}" if e and key in e else "–"

            lines.append(
                f"| {mesh} | {triangles(results, mesh):,} | {query} | {cell(ours)} | "
                f"{count(ours, 'nodes_visited', 0)} | {count(ours, 'triangles_tested', 1)} | "
                f"{cell(theirs)} | {count(theirs, 'triangles_tested', 1)} | {speed} |")
    lines.append("")
    lines.append("| mesh | triangles | sphere tree build [ms] | bytes / triangle | leaf spheres | depth | "
                 "CGAL AABB build + k-d tree [ms] |")
    lines.append("|---|---:|---:|---:|---:|---:|---:|")
    for mesh in meshes:
        ours = results.get(("Build", "SphereTree", mesh))
        theirs = results.get(("Build", "CgalAabb", mesh))
        if not ours:
            continue
        lines.append(
            f"| {mesh} | {triangles(results, mesh):,} | {ours['real_ns'] / 1e6:.0f} | "
            f"{ours.get('bytes_per_triangle', 0):.1f} | {int(ours.get('leaf_spheres', 0)):,} | "
            f"{int(ours.get('depth', 0))} | {(theirs['real_ns'] / 1e6 if theirs else float('nan')):.0f} |")
    lines.append("")
    # The targets, judged from the numbers above.
    lines.append(f"Targets at {TARGET_MESH} (1.3M triangles, r = 1 mm, 0.5 mm edges, segments ≤ 1 mm):")
    lines.append("")
    lines.append("| target | measured | met? |")
    lines.append("|---|---|---|")

    def verdict(ok):
        return "**met**" if ok else "**not met**"

    for query in ["FirstContact", "Nearest"]:
        ours = results.get((query, "SphereTree", TARGET_MESH))
        theirs = results.get((query, "CgalAabb", TARGET_MESH))
        if ours:
            lines.append(f"| {query} median < 2 µs | {fmt_us(ours['median_ns'])} µs | "
                         f"{verdict(ours['median_ns'] < 2000)} |")
        if ours and theirs:
            lines.append(f"| {query} faster than CGAL AABB (median) | {fmt_us(ours['median_ns'])} vs "
                         f"{fmt_us(theirs['median_ns'])} µs | "
                         f"{verdict(ours['median_ns'] < theirs['median_ns'])} |")
    build = results.get(("Build", "SphereTree", TARGET_MESH))
    if build:
        lines.append(f"| build < 1 s | {build['real_ns'] / 1e6:.0f} ms | {verdict(build['real_ns'] < 1e9)} |")
        lines.append(f"| tree < 64 bytes / triangle | {build.get('bytes_per_triangle', 0):.1f} B | "
                     f"{verdict(build.get('bytes_per_triangle', 1e9) < 64)} |")
    lines.append("")
    lines.append(f"Machine: {context.get('host_name', '?')}, {context.get('num_cpus', '?')} CPUs at "
                 f"{context.get('mhz_per_cpu', '?')} MHz, library build type "
                 f"{context.get('library_build_type', '?')} (Google Benchmark's own build), "
                 f"run {context.get('date', '?')}, load average {context.get('load_avg', '?')}.")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("results")
    parser.add_argument("--figures", required=True)
    parser.add_argument("--table", required=True)
    args = parser.parse_args()
    context, results = load(args.results)
    meshes = meshes_in(results)
    os.makedirs(args.figures, exist_ok=True)
    written = [plot_queries(results, meshes, args.figures), plot_build(results, meshes, args.figures)]
    with open(args.table, "w") as f:
        f.write(table(context, results, meshes))
    written.append(args.table)
    for path in written:
        print("wrote", path)


if __name__ == "__main__":
    main()
